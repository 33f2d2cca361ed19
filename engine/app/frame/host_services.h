// The engine's implementation of EngineServices: plugin requests routed to the host core (cvars,
// commands), the virtual filesystem, the loaded world, the palette and the GPU pass timers.
#pragma once

#include <array>
#include <functional>
#include <string_view>

#include "app/frame/plugin_commands.h"
#include "host/host_core.h"
#include "plugin/engine_services.h"

namespace nq {

class Vfs;
class GpuPassTimers;

struct HostServicesWiring {
    HostCore* host = nullptr;
    const Vfs* vfs = nullptr;             // may be null (showroom without data)
    GpuPassTimers* gpu_timers = nullptr;  // may be null (no GL)
    std::function<void(int level, std::string_view text)> log;
    // Traces against the loaded world; leaves `out` at fraction 1 when no map is loaded.
    std::function<void(const float start[3], const float end[3], nqr_trace* out)> trace;
    std::function<void*(const char* name)> gl_proc_address;
};

class HostServices : public EngineServices {
  public:
    explicit HostServices(HostServicesWiring wiring);

    // Palette and colormap handed to plugins; defaults are a grey ramp until set.
    void set_palette(const uint8_t (&rgb)[768]);
    void set_colormap(const uint8_t* table, size_t size);

    void log(int level, std::string_view text) override;
    const nqr_cvar* register_cvar(OwnerId owner, const char* name, const char* default_value,
                                  uint32_t flags, const char* description) override;
    void set_cvar(const char* name, const char* value) override;
    bool register_command(OwnerId owner, const char* name, nqr_command_fn fn, void* user,
                          const char* description) override;
    void release_owner(OwnerId owner) override;
    bool read_file(const char* path, std::vector<uint8_t>& out) override;
    void* gl_proc_address(const char* name) override;
    double real_time() override;
    void trace(const float start[3], const float end[3], nqr_trace* out) override;
    const uint8_t* palette() override { return palette_.data(); }
    const uint8_t* colormap() override { return colormap_.data(); }
    void gpu_pass_begin(const char* name) override;
    void gpu_pass_end() override;

  private:
    HostServicesWiring wiring_;
    PluginCommands plugin_commands_;
    std::array<uint8_t, 768> palette_{};
    std::array<uint8_t, 64 * 256 + 256> colormap_{};
};

}  // namespace nq

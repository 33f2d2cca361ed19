// What the engine offers renderer plugins, as a C++ interface. PluginHost adapts it to the C
// table nqr_engine; the engine implements it over its host core, VFS, world and video, and
// tests implement it with fakes.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "host/owner.h"
#include "nqr_renderer.h"

namespace nq {

class EngineServices {
public:
    virtual ~EngineServices() = default;

    virtual void log(int level, std::string_view text) = 0;
    virtual const nqr_cvar* register_cvar(OwnerId owner, const char* name,
                                          const char* default_value, uint32_t flags,
                                          const char* description) = 0;
    virtual void set_cvar(const char* name, const char* value) = 0;
    virtual bool register_command(OwnerId owner, const char* name, nqr_command_fn fn, void* user,
                                  const char* description) = 0;
    // Removes what a plugin registered (commands, callbacks); its cvars keep their values.
    virtual void release_owner(OwnerId owner) = 0;

    virtual bool read_file(const char* path, std::vector<uint8_t>& out) = 0;
    virtual void* gl_proc_address(const char* name) = 0;
    virtual double real_time() = 0;
    virtual void trace(const float start[3], const float end[3], nqr_trace* out) = 0;
    virtual const uint8_t* palette() = 0;   // 768 bytes
    virtual const uint8_t* colormap() = 0;  // 64 * 256 (+256) bytes
    virtual void gpu_pass_begin(const char* name) = 0;
    virtual void gpu_pass_end() = 0;
};

}  // namespace nq

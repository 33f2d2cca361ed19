// An EngineServices that does nothing and has nothing: the base of the plugin tests' fakes,
// which override what they record or serve.
#pragma once

#include <string_view>
#include <vector>

#include "plugin/engine_services.h"

namespace nq::test {

class NullEngineServices : public EngineServices {
  public:
    void log(int, std::string_view) override {}
    const nqr_cvar* register_cvar(OwnerId, const char*, const char*, uint32_t,
                                  const char*) override {
        return nullptr;
    }
    void set_cvar(const char*, const char*) override {}
    bool register_command(OwnerId, const char*, nqr_command_fn, void*, const char*) override {
        return false;
    }
    void release_owner(OwnerId) override {}
    bool read_file(const char*, std::vector<uint8_t>&) override { return false; }
    void* gl_proc_address(const char*) override { return nullptr; }
    double real_time() override { return 0; }
    void trace(const float*, const float*, nqr_trace*) override {}
    const uint8_t* palette() override { return nullptr; }
    const uint8_t* colormap() override { return nullptr; }
    void gpu_pass_begin(const char*) override {}
    void gpu_pass_end() override {}
};

}  // namespace nq::test

// What the driver reports about the OpenGL context the engine got.
#pragma once

#include <string>

namespace nq {

struct GlInfo {
    int major = 0, minor = 0;
    std::string version;   // GL_VERSION, e.g. "4.5 (Core Profile) Mesa 22.3.6"
    std::string renderer;  // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
    std::string vendor;    // GL_VENDOR
    std::string glsl_version;
    int swap_interval = 0;  // as SDL reports it: 0 = no vsync, 1 = vsync, -1 = adaptive
};

}  // namespace nq

// The engine's GLSL programs (2D quads, gamma), built by nprlib's gl::Program -- the one
// compile-and-link path of the engine and the styles -- with a failure as the engine's Error
// (the program's name as its file, the failing stage and the driver's log as its message).
#pragma once

#include <string>

#include "common/result.h"
#include "gl/program.h"

namespace nq {

Result<npr::gl::Program> build_program(const char* vertex_source, const char* fragment_source,
                                       const std::string& name);

}  // namespace nq

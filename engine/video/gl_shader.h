// Compiling and linking GLSL with the driver's log returned as an error, never printed.
#pragma once

#include <epoxy/gl.h>

#include <initializer_list>
#include <string>
#include <string_view>

#include "common/result.h"
#include "video/gl_objects.h"

namespace nq {

// `name` labels errors ("classic/world.frag"); `stage` is GL_VERTEX_SHADER, GL_FRAGMENT_SHADER,
// GL_GEOMETRY_SHADER, ... The error message holds the driver's info log.
Result<GlShader> compile_shader(GLenum stage, std::string_view source, const std::string& name);

// Links the shaders into a program (they may be deleted afterwards).
Result<GlProgram> link_program(std::initializer_list<GLuint> shaders, const std::string& name);

// compile_shader(vertex) + compile_shader(fragment) + link_program.
Result<GlProgram> build_program(std::string_view vertex_source, std::string_view fragment_source,
                                const std::string& name);

}  // namespace nq

#include "console/console_shader.h"

#include "video/gl_shader.h"

namespace nq {
namespace {

constexpr const char* kVertexSource = R"(#version 330 core
layout(location = 0) in vec2 position;
layout(location = 1) in vec2 uv;
layout(location = 2) in vec4 colour;
layout(location = 3) in float textured;
uniform vec2 screen_size;
out vec2 frag_uv;
out vec4 frag_colour;
out float frag_textured;
void main() {
    vec2 ndc = vec2(position.x / screen_size.x * 2.0 - 1.0, 1.0 - position.y / screen_size.y * 2.0);
    gl_Position = vec4(ndc, 0.0, 1.0);
    frag_uv = uv;
    frag_colour = colour;
    frag_textured = textured;
}
)";

constexpr const char* kFragmentSource = R"(#version 330 core
in vec2 frag_uv;
in vec4 frag_colour;
in float frag_textured;
uniform sampler2D image;
out vec4 out_colour;
void main() {
    vec4 texel = frag_textured > 0.5 ? texture(image, frag_uv) : vec4(1.0);
    out_colour = texel * frag_colour;
    if (out_colour.a <= 0.0) discard;  // transparent font pixels leave depth/stencil alone too
}
)";

}  // namespace

Result<GlProgram> build_console_program() {
    Result<GlProgram> program = build_program(kVertexSource, kFragmentSource, "console");
    if (!program) return program;
    GLint previous = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, &previous);
    glUseProgram(program->id());
    glUniform1i(glGetUniformLocation(program->id(), "image"), 0);
    glUseProgram(static_cast<GLuint>(previous));
    return program;
}

}  // namespace nq

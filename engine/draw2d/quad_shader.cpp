#include "draw2d/quad_shader.h"

#include "video/gl_shader.h"

namespace nq {
namespace {

constexpr const char* kVertexSource = R"(#version 330 core
layout(location = 0) in vec2 position;
layout(location = 1) in vec2 uv;
layout(location = 2) in vec4 colour;
layout(location = 3) in float sampling;
uniform vec2 screen_size;
out vec2 frag_uv;
out vec4 frag_colour;
flat out float frag_sampling;
void main() {
    vec2 ndc = vec2(position.x / screen_size.x * 2.0 - 1.0, 1.0 - position.y / screen_size.y * 2.0);
    gl_Position = vec4(ndc, 0.0, 1.0);
    frag_uv = uv;
    frag_colour = colour;
    frag_sampling = sampling;
}
)";

constexpr const char* kFragmentSource = R"(#version 330 core
in vec2 frag_uv;
in vec4 frag_colour;
flat in float frag_sampling;
uniform sampler2D image;
out vec4 out_colour;
void main() {
    // QuadSampling (quad_batch.h): 0 solid, 0.5 the texture's own filter, 1 the texel under
    // the pixel (crisp glyphs from a texture filtered for pictures).
    vec4 texel = vec4(1.0);
    if (frag_sampling > 0.75) {
        texel = texelFetch(image, ivec2(floor(frag_uv * vec2(textureSize(image, 0)))), 0);
    } else if (frag_sampling > 0.25) {
        texel = texture(image, frag_uv);
    }
    out_colour = texel * frag_colour;
    if (out_colour.a <= 0.0) discard;  // transparent font pixels leave depth/stencil alone too
}
)";

}  // namespace

Result<npr::gl::Program> build_quad_program() {
    Result<npr::gl::Program> program = build_program(kVertexSource, kFragmentSource, "2d quads");
    if (!program) return program;
    GLint previous = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, &previous);
    glUseProgram(program->id());
    glUniform1i(glGetUniformLocation(program->id(), "image"), 0);
    glUseProgram(static_cast<GLuint>(previous));
    return program;
}

}  // namespace nq

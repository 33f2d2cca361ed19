#include "video/gamma_pass.h"

#include <array>

#include "video/gl_shader.h"

namespace nq {
namespace {

// One triangle covering the screen; texel-exact reads of the copy.
constexpr const char* kVertexSource = R"(#version 330 core
void main() {
    vec2 corner = vec2(float((gl_VertexID & 1) << 2) - 1.0, float((gl_VertexID & 2) << 1) - 1.0);
    gl_Position = vec4(corner, 0.0, 1.0);
}
)";

constexpr const char* kFragmentSource = R"(#version 330 core
uniform sampler2D frame;
uniform float gamma;
uniform float contrast;
out vec4 out_colour;
void main() {
    vec3 colour = texelFetch(frame, ivec2(gl_FragCoord.xy), 0).rgb;
    out_colour = vec4(pow(min(colour * contrast, vec3(1.0)), vec3(gamma)), 1.0);
}
)";

// Puts back what apply() changes.
class GammaStateRestore {
  public:
    GammaStateRestore() {
        glGetIntegerv(GL_CURRENT_PROGRAM, &program_);
        glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertex_array_);
        glGetIntegerv(GL_ACTIVE_TEXTURE, &active_texture_);
        glActiveTexture(GL_TEXTURE0);
        glGetIntegerv(GL_TEXTURE_BINDING_2D, &texture_);
        glGetIntegerv(GL_VIEWPORT, viewport_.data());
        glGetBooleanv(GL_COLOR_WRITEMASK, colour_mask_.data());
        glGetIntegerv(GL_POLYGON_MODE, polygon_mode_.data());  // core: front and back are one
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
        for (size_t i = 0; i < kCapabilities.size(); ++i) {
            enabled_[i] = glIsEnabled(kCapabilities[i]);
            glDisable(kCapabilities[i]);
        }
    }
    ~GammaStateRestore() {
        for (size_t i = 0; i < kCapabilities.size(); ++i) {
            if (enabled_[i]) glEnable(kCapabilities[i]);
        }
        glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
        glColorMask(colour_mask_[0], colour_mask_[1], colour_mask_[2], colour_mask_[3]);
        glPolygonMode(GL_FRONT_AND_BACK, static_cast<GLenum>(polygon_mode_[0]));
        glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(texture_));
        glActiveTexture(static_cast<GLenum>(active_texture_));
        glBindVertexArray(static_cast<GLuint>(vertex_array_));
        glUseProgram(static_cast<GLuint>(program_));
    }
    GammaStateRestore(const GammaStateRestore&) = delete;
    GammaStateRestore& operator=(const GammaStateRestore&) = delete;

  private:
    static constexpr std::array<GLenum, 5> kCapabilities = {GL_BLEND, GL_DEPTH_TEST, GL_CULL_FACE,
                                                            GL_SCISSOR_TEST, GL_STENCIL_TEST};
    std::array<GLboolean, 5> enabled_{};
    std::array<GLint, 4> viewport_{};
    std::array<GLboolean, 4> colour_mask_{};
    std::array<GLint, 2> polygon_mode_{};
    GLint program_ = 0, vertex_array_ = 0, active_texture_ = 0, texture_ = 0;
};

}  // namespace

Result<GammaPass> GammaPass::create() {
    Result<npr::gl::Program> program = build_program(kVertexSource, kFragmentSource, "gamma");
    if (!program) return program.error();
    return GammaPass(std::move(*program));
}

GammaPass::GammaPass(npr::gl::Program program)
    : program_(std::move(program)), empty_vertex_array_(npr::gl::VertexArray::create(nullptr)) {
    gamma_location_ = glGetUniformLocation(program_.id(), "gamma");
    contrast_location_ = glGetUniformLocation(program_.id(), "contrast");
    GLint previous = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, &previous);
    glUseProgram(program_.id());
    glUniform1i(glGetUniformLocation(program_.id(), "frame"), 0);
    glUseProgram(static_cast<GLuint>(previous));
}

void GammaPass::apply(const ScreenLevels& levels, int width, int height) {
    if (levels.identity() || !(levels.gamma > 0) || !(levels.contrast > 0) || width <= 0 ||
        height <= 0) {
        return;
    }
    GammaStateRestore restore;
    if (!frame_copy_ || copy_width_ != width || copy_height_ != height) {
        if (!frame_copy_) frame_copy_ = npr::gl::Texture::create(nullptr);
        glBindTexture(GL_TEXTURE_2D, frame_copy_.id());
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                     nullptr);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        copy_width_ = width;
        copy_height_ = height;
    }
    glBindTexture(GL_TEXTURE_2D, frame_copy_.id());
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, width, height);
    glViewport(0, 0, width, height);
    glUseProgram(program_.id());
    glUniform1f(gamma_location_, levels.gamma);
    glUniform1f(contrast_location_, levels.contrast);
    glBindVertexArray(empty_vertex_array_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace nq

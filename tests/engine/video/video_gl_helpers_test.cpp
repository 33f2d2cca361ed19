// The engine's program builder: nprlib's gl::Program with failures as the engine's Error.
#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <optional>

#include "video/gl_shader.h"
#include "video/screenshot.h"
#include "support/video_test_support.h"

namespace nq {
namespace {

// A triangle covering the whole viewport, built from gl_VertexID (no vertex buffers).
constexpr const char* kFullscreenVertex = R"(#version 330 core
void main() {
    vec2 p = vec2((gl_VertexID & 1) * 4 - 1, (gl_VertexID & 2) * 2 - 1);
    gl_Position = vec4(p, 0.0, 1.0);
})";

constexpr const char* kUniformColourFragment = R"(#version 330 core
uniform vec3 colour;
out vec4 frag;
void main() { frag = vec4(colour, 1.0); })";

class VideoGlHelpers : public ::testing::Test {
  protected:
    void SetUp() override {
        auto created = test::make_offscreen_window();
        ASSERT_TRUE(created) << created.error().message;
        window.emplace(std::move(*created));
    }
    std::optional<VideoWindow> window;
};

TEST_F(VideoGlHelpers, BuiltProgramDrawsWhatItShould) {
    auto program = build_program(kFullscreenVertex, kUniformColourFragment, "fill");
    ASSERT_TRUE(program) << program.error().message;
    npr::gl::VertexArray vao = npr::gl::VertexArray::create(nullptr);
    glBindVertexArray(vao.id());
    glUseProgram(program->id());
    glUniform3f(glGetUniformLocation(program->id(), "colour"), 1.0f, 0.0f, 1.0f);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glDrawArrays(GL_TRIANGLES, 0, 3);

    auto image = read_framebuffer_rgb(0, 64, 48);
    ASSERT_TRUE(image) << image.error().message;
    for (size_t i = 0; i < image->rgb.size(); i += 3) {
        ASSERT_EQ(image->rgb[i], 255) << "pixel " << i / 3;
        ASSERT_EQ(image->rgb[i + 1], 0);
        ASSERT_EQ(image->rgb[i + 2], 255);
    }
}

// nprlib_gl_test checks gl::Program's compile and link errors; here the engine's Error carries
// the program's name and the failing stage.
TEST_F(VideoGlHelpers, FailingStageIsNamedInBuildProgram) {
    auto program = build_program("#version 330 core\nvoid main() { undefined_call(); }\n",
                                 kUniformColourFragment, "bad_vertex");
    ASSERT_FALSE(program);
    EXPECT_EQ(program.error().file, "bad_vertex");
    EXPECT_EQ(program.error().message.rfind("vertex shader failed to compile", 0), 0u)
        << program.error().message;
}

}  // namespace
}  // namespace nq

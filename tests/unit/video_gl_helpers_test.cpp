// Shader compile/link with logs returned, and the RAII owners of GL objects.
#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <optional>

#include "video/gl_objects.h"
#include "video/gl_shader.h"
#include "video/screenshot.h"
#include "video_test_support.h"

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

TEST_F(VideoGlHelpers, CompileErrorReturnsTheDriversLog) {
    auto shader = compile_shader(GL_FRAGMENT_SHADER,
                                 "#version 330 core\nout vec4 c;\nvoid main() { c = vec4(1.0) }\n",
                                 "broken.frag");
    ASSERT_FALSE(shader);
    EXPECT_EQ(shader.error().file, "broken.frag");
    const std::string& message = shader.error().message;
    EXPECT_EQ(message.rfind("fragment shader failed to compile:\n", 0), 0u) << message;
    // The log itself follows the headline, and it names the problem line (3).
    std::string log = message.substr(message.find('\n') + 1);
    EXPECT_GT(log.size(), 5u);
    EXPECT_NE(log.find('3'), std::string::npos) << log;
}

TEST_F(VideoGlHelpers, LinkErrorReturnsTheLog) {
    auto vertex = compile_shader(GL_VERTEX_SHADER, kFullscreenVertex, "v");
    ASSERT_TRUE(vertex) << vertex.error().message;
    // Compiles (a library shader), but a program needs a main in every stage.
    auto fragment = compile_shader(GL_FRAGMENT_SHADER,
                                   "#version 330 core\nvec4 helper() { return vec4(1.0); }\n", "f");
    ASSERT_TRUE(fragment) << fragment.error().message;
    auto program = link_program({vertex->id(), fragment->id()}, "no_main");
    ASSERT_FALSE(program);
    EXPECT_EQ(program.error().file, "no_main");
    EXPECT_EQ(program.error().message.rfind("program failed to link:\n", 0), 0u);
    EXPECT_GT(program.error().message.size(), std::string("program failed to link:\n").size());
}

TEST_F(VideoGlHelpers, BuiltProgramDrawsWhatItShould) {
    auto program = build_program(kFullscreenVertex, kUniformColourFragment, "fill");
    ASSERT_TRUE(program) << program.error().message;
    GlVertexArray vao = GlVertexArray::generate();
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

TEST_F(VideoGlHelpers, FailingStageIsNamedInBuildProgram) {
    auto program = build_program("#version 330 core\nvoid main() { undefined_call(); }\n",
                                 kUniformColourFragment, "bad_vertex");
    ASSERT_FALSE(program);
    EXPECT_EQ(program.error().message.rfind("vertex shader failed to compile", 0), 0u);
}

TEST_F(VideoGlHelpers, OwnersDeleteTheirObjects) {
    GLuint id = 0;
    {
        GlBuffer buffer = GlBuffer::generate();
        id = buffer.id();
        ASSERT_NE(id, 0u);
        glBindBuffer(GL_ARRAY_BUFFER, id);  // a generated name becomes an object when bound
        EXPECT_TRUE(glIsBuffer(id));
        GlBuffer moved = std::move(buffer);
        EXPECT_EQ(buffer.id(), 0u);
        EXPECT_EQ(moved.id(), id);
    }
    EXPECT_FALSE(glIsBuffer(id));

    GlTexture texture = GlTexture::generate();
    GLuint tex_id = texture.id();
    glBindTexture(GL_TEXTURE_2D, tex_id);
    EXPECT_TRUE(glIsTexture(tex_id));
    GLuint released = texture.release();  // the caller owns it now
    EXPECT_EQ(released, tex_id);
    EXPECT_FALSE(texture);
    EXPECT_TRUE(glIsTexture(tex_id));
    glDeleteTextures(1, &released);
}

TEST_F(VideoGlHelpers, OwnerOutlivingTheContextDoesNotTouchGl) {
    GlBuffer buffer = GlBuffer::generate();
    EXPECT_NE(buffer.id(), 0u);
    window.reset();  // context gone (and the buffer with it)
    EXPECT_FALSE(gl_context_is_current());
    buffer.reset();  // must not call GL without a context
    EXPECT_EQ(buffer.id(), 0u);
}

}  // namespace
}  // namespace nq

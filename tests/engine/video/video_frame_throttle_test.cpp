// FrameThrottle on a real (software) GL context: llvmpipe on an offscreen pbuffer queues frames
// without limit, and with the throttle a frame is handed over only once the one before it is
// finished. The test fences each frame itself, just before the throttle does: a fence
// completes only after every command before it, so the throttle having waited for its own
// fence of a frame means the test's fence of that frame is signalled too.
#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <optional>
#include <vector>

#include "gl/program.h"
#include "video/frame_throttle.h"
#include "video/gl_context_setup.h"
#include "video/gl_shader.h"
#include "support/video_test_support.h"

namespace nq {
namespace {

constexpr int kWidth = 256;
constexpr int kHeight = 192;
constexpr int kFrames = 12;

constexpr const char* kVertex = R"(#version 330 core
void main() {
    vec2 p = vec2((gl_VertexID & 1) * 4 - 1, (gl_VertexID & 2) * 2 - 1);
    gl_Position = vec4(p, 0.0, 1.0);
})";
// Slow on purpose: drawing a frame takes the rasteriser far longer than submitting it.
constexpr const char* kSlowFragment = R"(#version 330 core
out vec4 frag;
void main() {
    float v = gl_FragCoord.x * 0.001;
    for (int i = 0; i < 200; ++i) v = sin(v * 1.7 + gl_FragCoord.y * 0.01);
    frag = vec4(v, 0.5, 0.25, 1.0);
})";

bool signalled(GLsync fence) {
    GLint status = GL_UNSIGNALED;
    glGetSynciv(fence, GL_SYNC_STATUS, 1, nullptr, &status);
    return status == GL_SIGNALED;
}

class VideoFrameThrottle : public ::testing::Test {
  protected:
    void SetUp() override {
        auto created = test::make_offscreen_window(kWidth, kHeight);
        ASSERT_TRUE(created) << created.error().message;
        window.emplace(std::move(*created));
        auto built = build_program(kVertex, kSlowFragment, "slow_fill");
        ASSERT_TRUE(built) << built.error().message;
        program = std::move(*built);
        vao = npr::gl::VertexArray::create(nullptr);
    }
    void TearDown() override {
        for (GLsync fence : fences) glDeleteSync(fence);
        vao.reset();
        program.reset();
    }

    void draw_frame() {
        glViewport(0, 0, kWidth, kHeight);
        glBindVertexArray(vao.id());
        glUseProgram(program.id());
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    // Swaps, then fences the frame (the test's own fence).
    void swap_frame() {
        window->swap();
        fences.push_back(glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0));
        glFlush();
    }
    void submit_frame() {
        draw_frame();
        swap_frame();
    }

    std::optional<VideoWindow> window;
    npr::gl::Program program;
    npr::gl::VertexArray vao;
    std::vector<GLsync> fences;
};

// The premise: without a throttle the driver lets frames pile up, so right after submitting a
// frame, the one two before it is still being drawn.
TEST_F(VideoFrameThrottle, WithoutItTheDriverQueuesFrames) {
    int unfinished_two_back = 0;
    for (int n = 0; n < kFrames; ++n) {
        submit_frame();
        if (n >= 2 && !signalled(fences[n - 2])) ++unfinished_two_back;
    }
    EXPECT_GT(unfinished_two_back, 0);
}

TEST_F(VideoFrameThrottle, AFrameIsSwappedOnlyOnceTheOneBeforeItIsFinished) {
    FrameThrottle throttle;
    for (int n = 0; n < kFrames; ++n) {
        draw_frame();
        throttle.before_swap();
        if (n >= 1) {
            EXPECT_TRUE(signalled(fences[n - 1])) << "frame " << n - 1 << " before swapping " << n;
        }
        swap_frame();
        throttle.after_swap();
    }
    throttle.release();
}

// A caller that skips before_swap() (nothing to wait for yet, or a frame drawn outside the
// loop) leaks no fence and the next wait is for the newest frame.
TEST_F(VideoFrameThrottle, SwapsWithoutAWaitKeepOnlyTheNewestFence) {
    FrameThrottle throttle;
    for (int n = 0; n < 3; ++n) {
        submit_frame();
        throttle.after_swap();
    }
    draw_frame();
    throttle.before_swap();
    EXPECT_TRUE(signalled(fences[2]));
    throttle.release();
}

// A throttle that outlives its context must not call GL (there is nothing left to delete).
TEST_F(VideoFrameThrottle, OutlivingTheContextIsHarmless) {
    FrameThrottle throttle;
    submit_frame();
    throttle.after_swap();
    for (GLsync fence : fences) glDeleteSync(fence);
    fences.clear();
    vao.reset();
    program.reset();
    window.reset();
    EXPECT_FALSE(gl_context_is_current());
    throttle.release();
}

}  // namespace
}  // namespace nq

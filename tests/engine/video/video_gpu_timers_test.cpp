// GPU pass timers on a real (software) GL context.
#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <optional>

#include "gl/program.h"
#include "video/gl_shader.h"
#include "video/gpu_pass_timers.h"
#include "support/video_test_support.h"

namespace nq {
namespace {

constexpr const char* kVertex = R"(#version 330 core
void main() {
    vec2 p = vec2((gl_VertexID & 1) * 4 - 1, (gl_VertexID & 2) * 2 - 1);
    gl_Position = vec4(p, 0.0, 1.0);
})";
constexpr const char* kFragment = R"(#version 330 core
out vec4 frag;
void main() { frag = vec4(0.5, 0.25, 1.0, 1.0); })";

class VideoGpuTimers : public ::testing::Test {
  protected:
    void SetUp() override {
        auto created = test::make_offscreen_window();
        ASSERT_TRUE(created) << created.error().message;
        window.emplace(std::move(*created));
        auto built = build_program(kVertex, kFragment, "timer_fill");
        ASSERT_TRUE(built) << built.error().message;
        program = std::move(*built);
        vao = npr::gl::VertexArray::create(nullptr);
        ASSERT_TRUE(timers.init()) << "llvmpipe supports GL_TIMESTAMP queries";
    }
    void TearDown() override {
        timers.shutdown();
        vao.reset();
        program.reset();
    }

    void draw() {
        glBindVertexArray(vao.id());
        glUseProgram(program.id());
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }

    // One frame: a world pass with a draw and a plugin pass with a draw.
    void frame() {
        timers.begin_frame();
        timers.begin(GpuPass::World);
        draw();
        timers.end();
        timers.begin("outline");
        draw();
        timers.end();
        timers.end_frame();
        window->swap();
    }

    std::optional<VideoWindow> window;
    npr::gl::Program program;
    npr::gl::VertexArray vao;
    GpuPassTimers timers;
};

const GpuPassTotals* find(const std::vector<GpuPassTotals>& totals, const std::string& name) {
    for (const auto& t : totals) {
        if (t.name == name) return &t;
    }
    return nullptr;
}

TEST_F(VideoGpuTimers, PassWithADrawGetsANonNegativeTimeEveryFrame) {
    for (int i = 0; i < 6; ++i) frame();
    timers.finish();
    EXPECT_EQ(timers.frames_timed(), 6u);
    EXPECT_EQ(timers.pass_count("world"), 6u);
    EXPECT_EQ(timers.pass_count("outline"), 6u);
    EXPECT_EQ(timers.pass_count("alias"), 0u);
    EXPECT_EQ(timers.total_nanoseconds("alias"), 0u);

    std::vector<GpuPassTotals> totals = timers.totals();
    ASSERT_EQ(totals.size(), size_t{kBuiltinGpuPasses + 1});  // plugin passes follow built-ins
    EXPECT_EQ(totals[0].name, "world");
    EXPECT_EQ(totals[5].name, "post");
    EXPECT_EQ(totals[6].name, "outline");
    const GpuPassTotals* world = find(totals, "world");
    ASSERT_NE(world, nullptr);
    EXPECT_GE(world->total_ms, 0.0);
    EXPECT_DOUBLE_EQ(world->ms_per_frame, world->total_ms / 6);
    EXPECT_DOUBLE_EQ(world->total_ms, timers.total_nanoseconds("world") / 1e6);
    const GpuTimerDiagnostics& d = timers.diagnostics();
    EXPECT_EQ(d.dropped_passes, 0u);
    EXPECT_EQ(d.unknown_passes, 0u);
    EXPECT_EQ(d.unbalanced, 0u);
}

TEST_F(VideoGpuTimers, TotalsAccumulateAcrossFrames) {
    for (int i = 0; i < 3; ++i) frame();
    timers.finish();
    uint64_t world_after_3 = timers.total_nanoseconds("world");
    uint64_t outline_after_3 = timers.total_nanoseconds("outline");
    EXPECT_EQ(timers.pass_count("world"), 3u);

    for (int i = 0; i < 10; ++i) frame();  // more than the ring is deep
    timers.finish();
    EXPECT_EQ(timers.pass_count("world"), 13u);
    EXPECT_EQ(timers.frames_timed(), 13u);
    EXPECT_GE(timers.total_nanoseconds("world"), world_after_3);
    EXPECT_GE(timers.total_nanoseconds("outline"), outline_after_3);

    timers.reset();
    EXPECT_EQ(timers.pass_count("world"), 0u);
    EXPECT_EQ(timers.total_nanoseconds("world"), 0u);
    EXPECT_EQ(timers.frames_timed(), 0u);
}

// Exclusive time: the outer pass loses what the inner one measured, so together they equal
// the outer span as measured by our own pair of timestamp queries around it.
TEST_F(VideoGpuTimers, NestedPassTimeIsExclusive) {
    GLuint span[2];
    glGenQueries(2, span);
    timers.begin_frame();
    glQueryCounter(span[0], GL_TIMESTAMP);
    timers.begin(GpuPass::Post);
    draw();
    timers.begin("inner");
    draw();
    draw();
    timers.end();
    draw();
    timers.end();
    glQueryCounter(span[1], GL_TIMESTAMP);
    timers.end_frame();
    timers.finish();
    GLuint64 t0 = 0, t1 = 0;
    glGetQueryObjectui64v(span[0], GL_QUERY_RESULT, &t0);
    glGetQueryObjectui64v(span[1], GL_QUERY_RESULT, &t1);
    glDeleteQueries(2, span);

    EXPECT_EQ(timers.pass_count("post"), 1u);
    EXPECT_EQ(timers.pass_count("inner"), 1u);
    uint64_t sum = timers.total_nanoseconds("post") + timers.total_nanoseconds("inner");
    EXPECT_LE(sum, t1 - t0);  // our queries sit just outside the timers' own
}

TEST_F(VideoGpuTimers, MisuseIsCountedNotFatal) {
    timers.begin_frame();
    timers.end();  // nothing open
    timers.begin(GpuPass::Alias);
    draw();
    timers.end_frame();  // alias still open: closed for it
    timers.finish();
    EXPECT_EQ(timers.diagnostics().unbalanced, 2u);
    EXPECT_EQ(timers.pass_count("alias"), 1u);
}

TEST_F(VideoGpuTimers, PluginNameTableIsBounded) {
    timers.begin_frame();
    for (int i = 0; i < kMaxPluginGpuPasses; ++i) {
        timers.begin("plugin" + std::to_string(i));
        timers.end();
    }
    timers.begin("one_too_many");
    timers.end();
    timers.begin(std::string(kMaxGpuPassNameLength + 1, 'x'));
    timers.end();
    timers.begin("");
    timers.end();
    timers.begin(static_cast<const char*>(nullptr));  // a plugin's mistake through the ABI
    timers.end();
    timers.end_frame();
    timers.finish();
    EXPECT_EQ(timers.diagnostics().unknown_passes, 4u);
    EXPECT_EQ(timers.diagnostics().unbalanced, 0u);  // ignored begins still pair with ends
    EXPECT_EQ(timers.totals().size(), size_t{kMaxGpuPasses});
    EXPECT_EQ(timers.pass_count("plugin15"), 1u);
    EXPECT_EQ(timers.pass_count("one_too_many"), 0u);
}

TEST_F(VideoGpuTimers, MarkerBudgetDropsPassesButKeepsPairs) {
    timers.begin_frame();
    timers.begin(GpuPass::World);  // stays open across the flood below
    for (int i = 0; i < kMaxGpuMarkersPerFrame; ++i) {
        timers.begin(GpuPass::Particles);
        timers.end();
    }
    timers.end();
    timers.end_frame();
    timers.finish();
    EXPECT_EQ(timers.pass_count("world"), 1u);
    EXPECT_GT(timers.diagnostics().dropped_passes, 0u);
    EXPECT_EQ(timers.pass_count("particles") + timers.diagnostics().dropped_passes,
              uint64_t{kMaxGpuMarkersPerFrame});
    EXPECT_EQ(timers.diagnostics().unbalanced, 0u);
}

TEST_F(VideoGpuTimers, DisabledTimersDoNothing) {
    GpuPassTimers off;
    EXPECT_FALSE(off.init(false));
    EXPECT_FALSE(off.active());
    off.begin_frame();
    off.begin(GpuPass::World);
    draw();
    off.end();
    off.end();
    off.end_frame();
    off.finish();
    EXPECT_EQ(off.frames_timed(), 0u);
    EXPECT_EQ(off.pass_count("world"), 0u);
    EXPECT_EQ(off.diagnostics().unbalanced, 0u);
    for (const GpuPassTotals& t : off.totals()) EXPECT_EQ(t.count, 0u);
}

}  // namespace
}  // namespace nq

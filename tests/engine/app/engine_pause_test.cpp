// `pause` freezes a demo on one frame (drawn identically again and again, not counted by
// timedemo, demo_at still counting demo frames), and `showroom_time` holds the showroom still
// so that its screenshots are reproducible.
#include <gtest/gtest.h>

#include "support/engine_demo_replay.h"
#include "support/engine_image_checks.h"
#include "support/engine_output_checks.h"
#include "support/engine_runs.h"

namespace nq {
namespace {

using namespace test;

constexpr uint64_t kPauseFrame = 200;

// Pixels that differ between two screenshots of the same size.
size_t differing_pixels(const RgbImage& a, const RgbImage& b) {
    size_t n = 0;
    for (size_t i = 0; i + 2 < a.rgb.size(); i += 3) {
        n += a.rgb[i] != b.rgb[i] || a.rgb[i + 1] != b.rgb[i + 1] || a.rgb[i + 2] != b.rgb[i + 2];
    }
    return n;
}

// `timedemo demo` paused at demo frame 200 for several drawn frames: screenshots "held_a" and
// "held_b" are taken three drawn frames apart while paused; "moved" three demo frames after
// the unpause, and "after" at demo frame 300, one of the frames the unpaused run
// engine_runs::demo_classic() (same size and settings) screenshots. After 310 the null renderer
// plays the rest (faster; nothing left to look at).
constexpr uint64_t kAfterFrame = 300;
static_assert(engine_runs::kScreenshotFrames[1] == kAfterFrame);

const SharedRun& paused_demo() {
    return shared_nprquake_run("demo_pause", [](const std::string& dir) {
        auto args = engine_runs::base_args(dir, data_root(), "lq1");
        engine_runs::demo_at(args, kPauseFrame,
                             "pause 1; wait; wait; screenshot " + dir +
                                 "/held_a.png; wait; wait; wait; screenshot " + dir +
                                 "/held_b.png; pause 0");
        engine_runs::demo_at(args, kPauseFrame + 3, "screenshot " + dir + "/moved.png");
        engine_runs::demo_at(args, kAfterFrame, "screenshot " + dir + "/after.png");
        engine_runs::demo_at(args, kAfterFrame + 10, "r_plugin null");
        engine_runs::add(args, {"+timedemo", "demo", "+quit"});
        return args;
    });
}

TEST(EnginePause, PausedDemoDrawsTheSameFrameAgain) {
    const SharedRun& run = paused_demo();
    expect_clean_exit(run.result);
    RgbImage held_a, held_b, moved;
    ASSERT_NO_FATAL_FAILURE(load_screenshot(run.dir + "/held_a.png", held_a));
    ASSERT_NO_FATAL_FAILURE(load_screenshot(run.dir + "/held_b.png", held_b));
    ASSERT_NO_FATAL_FAILURE(load_screenshot(run.dir + "/moved.png", moved));
    ASSERT_EQ(held_a.width, engine_runs::kWidth);
    ASSERT_EQ(held_a.height, engine_runs::kHeight);
    EXPECT_GT(region_stats(held_a, whole(held_a)).distinct_colours, 1000u) << "not the level";
    EXPECT_EQ(differing_pixels(held_a, held_b), 0u);
    // The control: three demo frames on, the same run draws something else, so frames drawn
    // three apart would differ had the pause not held the demo.
    EXPECT_GT(differing_pixels(held_a, moved), 500u);
}

TEST(EnginePause, PauseAndUnpauseAreReportedOnce) {
    const SharedRun& run = paused_demo();
    expect_clean_exit(run.result);
    const std::string& out = run.result.out;
    EXPECT_EQ(lines_containing(out, "paused").size(), 2u) << out;  // "paused", "unpaused"
    size_t paused = out.find("\npaused\n");
    size_t unpaused = out.find("\nunpaused\n");
    ASSERT_NE(paused, std::string::npos) << out;
    ASSERT_NE(unpaused, std::string::npos) << out;
    EXPECT_LT(paused, unpaused);
}

// After the pause the demo goes on exactly as in a run that never paused, and demo_at counts
// demo frames: frame 300 is drawn pixel for pixel as the unpaused run draws it. (Had demo_at
// counted drawn frames, six of them paused, this shot would show demo frame 294.)
TEST(EnginePause, PauseLeavesNoTraceAndDemoAtCountsDemoFrames) {
    const SharedRun& run = paused_demo();
    const SharedRun& unpaused = engine_runs::demo_classic();
    expect_clean_exit(run.result);
    expect_clean_exit(unpaused.result);
    RgbImage after, reference;
    ASSERT_NO_FATAL_FAILURE(load_screenshot(run.dir + "/after.png", after));
    ASSERT_NO_FATAL_FAILURE(
        load_screenshot(engine_runs::shot(unpaused.dir, "classic", kAfterFrame), reference));
    ASSERT_EQ(after.rgb.size(), reference.rgb.size());
    EXPECT_EQ(differing_pixels(after, reference), 0u);
}

TEST(EnginePause, TimedemoCountsOnlyTheFramesItPlayed) {
    const SharedRun& run = paused_demo();
    expect_clean_exit(run.result);
    auto lines = timedemo_lines(run.result.out);
    ASSERT_EQ(lines.size(), 1u) << run.result.out;
    Vfs vfs = mount_lq1();
    EXPECT_EQ(lines[0].frames, timedemo_frame_count(vfs, "demo.dem"));
    expect_consistent_fps(lines[0]);
}

// A showroom run (no game data) taking a screenshot at each showroom_time given.
ProcessResult showroom_shots(const TempDir& dir, const std::string& run_name,
                             const std::vector<std::pair<std::string, std::string>>& shots) {
    std::string empty = dir.subdir(run_name + "_empty");
    auto args = engine_runs::base_args(dir.path() + "/" + run_name, empty, "");
    engine_runs::add(args, {"+pause"});  // no demo: refused
    for (const auto& [time, file] : shots) {
        engine_runs::add(args,
                         {"+showroom_time", time, "+wait", "+wait", "+screenshot", dir.file(file)});
    }
    engine_runs::add(args, {"+quit"});
    return run_nprquake(args, dir.path(), 60);
}

TEST(EnginePause, ShowroomTimeHoldsTheSceneStillAcrossRuns) {
    TempDir dir("nq_engine_showroom_time");
    ProcessResult first = showroom_shots(dir, "first", {{"5", "t5_first.png"}, {"6", "t6.png"}});
    ProcessResult second = showroom_shots(dir, "second", {{"5", "t5_second.png"}});
    expect_clean_exit(first);
    expect_clean_exit(second);
    EXPECT_EQ(lines_containing(first.out, "pause: no demo is playing").size(), 1u) << first.out;
    RgbImage t5_first, t5_second, t6;
    ASSERT_NO_FATAL_FAILURE(load_screenshot(dir.file("t5_first.png"), t5_first));
    ASSERT_NO_FATAL_FAILURE(load_screenshot(dir.file("t5_second.png"), t5_second));
    ASSERT_NO_FATAL_FAILURE(load_screenshot(dir.file("t6.png"), t6));
    expect_showroom_colours(t5_first);
    EXPECT_EQ(differing_pixels(t5_first, t5_second), 0u);
    // One second turns the models by 30 degrees: many pixels change.
    EXPECT_GT(differing_pixels(t5_first, t6), 200u);
}

}  // namespace
}  // namespace nq

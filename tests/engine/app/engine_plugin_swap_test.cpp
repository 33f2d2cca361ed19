// Renderer plugins swapped in the running engine binary: mid-demo swaps keep the demo and the
// picture going, a plugin of the wrong ABI is refused with its reason while the current one
// stays, and fifty swaps end cleanly with nothing leaked (the child runs under LeakSanitizer in
// the asan preset; any sanitizer report fails the test).
#include <gtest/gtest.h>

#include "support/engine_image_checks.h"
#include "support/engine_output_checks.h"
#include "support/engine_runs.h"
#include "support/build_paths.h"

namespace nq {
namespace {

using namespace test;
using engine_runs::kHeight;
using engine_runs::kWidth;

size_t count_lines(const std::string& text, const std::string& line) {
    size_t n = 0;
    for (const auto& l : lines_containing(text, line)) n += l == line;
    return n;
}

TEST(EnginePluginSwap, SwapsMidDemoKeepTheDemoAndThePictureGoing) {
    const SharedRun& run = engine_runs::demo2_swaps();
    expect_clean_exit(run.result);
    const std::string& out = run.result.out;
    EXPECT_EQ(timedemo_lines(out).size(), 1u) << out;
    // The start-up load and the two swaps back: classic three times; null twice.
    EXPECT_EQ(count_lines(out, "renderer: classic"), 3u) << out;
    EXPECT_EQ(count_lines(out, "renderer: null"), 2u) << out;
    EXPECT_TRUE(lines_containing(out, "keeping").empty()) << out;

    RgbImage null_shot, classic_shot;
    ASSERT_NO_FATAL_FAILURE(load_screenshot(
        engine_runs::shot(run.dir, "null", engine_runs::kDemo2NullShot), null_shot));
    ASSERT_NO_FATAL_FAILURE(load_screenshot(
        engine_runs::shot(run.dir, "classic", engine_runs::kDemo2ClassicShot), classic_shot));

    // The null renderer draws nothing: the cleared screen, black to the last pixel.
    RegionStats null_stats = region_stats(null_shot, whole(null_shot));
    EXPECT_EQ(null_stats.distinct_colours, 1u);
    EXPECT_TRUE(is_black(pixel(null_shot, kWidth / 2, kHeight / 2)));
    // Back on classic, the world is drawn again.
    RegionStats classic_stats = region_stats(classic_shot, whole(classic_shot));
    EXPECT_GT(classic_stats.distinct_colours, 1000u);
    EXPECT_GT(classic_stats.luminance_stddev, 12.0);
    EXPECT_GT(classic_stats.mean_luminance, 20.0);
}

TEST(EnginePluginSwap, WrongAbiIsRefusedWithItsReasonAndTheCurrentPluginStays) {
    TempDir dir("nq_engine_badabi");
    auto args = engine_runs::base_args(dir.path(), dir.subdir("empty"), "");  // the showroom
    engine_runs::add(args, {"-plugindir", test_plugin_dir(), "+r_plugin", "test_probe", "+r_plugin",
                            "test_badabi", "+wait", "+r_plugin", "+wait", "+screenshot",
                            dir.file("after.png"), "+quit"});
    ProcessResult r = run_nprquake(args, dir.path(), 60);
    expect_clean_exit(r);
    auto refused = lines_containing(r.out, "ABI version mismatch");
    ASSERT_EQ(refused.size(), 1u) << r.out;
    EXPECT_NE(refused[0].find("nqr_test_badabi"), std::string::npos) << refused[0];
    EXPECT_NE(refused[0].find("keeping probe"), std::string::npos) << refused[0];
    // The engine goes on with the probe plugin: `r_plugin` names it, and the frames after the
    // refusal are drawn (the probe leaves every draw hook to the engine's classic defaults).
    EXPECT_EQ(count_lines(r.out, "renderer: probe (r_plugins lists the others)"), 1u) << r.out;
    RgbImage after;
    ASSERT_NO_FATAL_FAILURE(load_screenshot(dir.file("after.png"), after));
    expect_showroom_colours(after);
}

TEST(EnginePluginSwap, FiftySwapsEndCleanlyWithNothingLeaked) {
    TempDir dir("nq_engine_fifty");
    auto args = engine_runs::base_args(dir.path(), dir.subdir("empty"), "");  // the showroom
    // Fifty swaps, each followed by a drawn frame. (Swapping on a demo's level costs seconds
    // per classic load under ASan — it registers every model — so the showroom carries the
    // count; demo2_swaps swaps on a real level.)
    for (int i = 1; i <= 50; ++i) {
        engine_runs::add(args, {"+r_plugin", i % 2 ? "null" : "classic", "+wait"});
    }
    engine_runs::add(args, {"+screenshot", dir.file("after.png"), "+quit"});
    ProcessResult r = run_nprquake(args, dir.path(), 120);
    expect_clean_exit(r);  // includes: no LeakSanitizer report
    EXPECT_EQ(count_lines(r.out, "renderer: null"), 25u) << r.out;
    EXPECT_EQ(count_lines(r.out, "renderer: classic"), 25u) << r.out;
    EXPECT_TRUE(lines_containing(r.out, "keeping").empty()) << r.out;
    RgbImage after;
    ASSERT_NO_FATAL_FAILURE(load_screenshot(dir.file("after.png"), after));
    expect_showroom_colours(after);
}

}  // namespace
}  // namespace nq

// The `illustrative` plugin in the running engine on a real demo: demo.dem plays to the end
// under it with every frame counted through swaps among classic, technical and illustrative
// mid-demo, and on a paused frame the style's pictures are its own: the models
// differ from classic while the world stays lit by the same lightmaps, and the terms shown on
// their own (ill_show) are what they claim to be.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "support/engine_demo_replay.h"
#include "support/engine_image_checks.h"
#include "support/engine_output_checks.h"
#include "support/engine_runs.h"

namespace nq {
namespace {

using namespace test;

constexpr uint64_t kPausedFrame = 760;  // the monster gallery of demo.dem (see engine_runs.h)

// demo.dem under illustrative, swapped through every style and back mid-demo (also over
// itself), with pictures of one paused frame in each style and three ill_show terms.
const SharedRun& demo_illustrative() {
    return shared_nprquake_run(
        "demo_illustrative",
        [](const std::string& dir) {
            auto args = engine_runs::base_args(dir, data_root(), "lq1");
            engine_runs::add(args, {"+scr_drawhud", "0", "+gl_polyblend", "0", "+r_plugin",
                                    "illustrative"});
            const auto shot = [&](const std::string& name) {
                return "wait; wait; screenshot " + dir + "/" + name + ".png; ";
            };
            engine_runs::demo_at(args, 300, "r_plugin technical");
            engine_runs::demo_at(args, 400, "r_plugin illustrative");
            engine_runs::demo_at(args, 500, "r_plugin illustrative; wait; r_plugin classic");
            engine_runs::demo_at(args, 600, "r_plugin illustrative");
            engine_runs::demo_at(args, kPausedFrame,
                                 "pause 1; " + shot("illustrative") + "ill_show 1; " +
                                     shot("albedo") + "ill_show 7; " + shot("view_dependent") +
                                     "ill_show 0; r_plugin technical; " + shot("technical") +
                                     "r_plugin classic; " + shot("classic") +
                                     "r_plugin illustrative; pause 0");
            engine_runs::add(args, {"+timedemo", "demo", "+quit"});
            return args;
        },
        600);
}

RgbImage load(const SharedRun& run, const std::string& name) {
    RgbImage image;
    load_screenshot(run.dir + "/" + name + ".png", image);
    return image;
}

size_t differing_pixels(const RgbImage& a, const RgbImage& b, int tolerance) {
    size_t n = 0;
    for (int y = 0; y < a.height; ++y) {
        for (int x = 0; x < a.width; ++x) n += !near_colour(pixel(a, x, y), pixel(b, x, y), tolerance);
    }
    return n;
}

TEST(IllustrativeDemo, DemoPlaysToTheEndWithSwapsAmongEveryStyle) {
    const SharedRun& run = demo_illustrative();
    ASSERT_NO_FATAL_FAILURE(expect_whole_timedemo(run, "demo.dem"));
    const std::string& out = run.result.out;
    // Loaded at start-up, at frames 400, 500 (again over itself), 600 and after the pictures.
    EXPECT_EQ(lines_containing(out, "renderer: illustrative").size(), 5u) << out;
    EXPECT_TRUE(lines_containing(out, "keeping").empty()) << out;
}

// demo2.dem (its map restart included) under illustrative, swapped to the other styles and back.
TEST(IllustrativeDemo, Demo2PlaysToTheEndWithSwapsAmongEveryStyle) {
    const SharedRun& run = shared_nprquake_run(
        "demo2_illustrative",
        [](const std::string& dir) {
            auto args = engine_runs::base_args(dir, data_root(), "lq1");
            engine_runs::add(args, {"+r_plugin", "illustrative"});
            engine_runs::demo_at(args, 400, "r_plugin technical");
            engine_runs::demo_at(args, 700, "r_plugin illustrative");
            engine_runs::demo_at(args, 1000, "r_plugin classic; wait; r_plugin illustrative");
            engine_runs::add(args, {"+timedemo", "demo2", "+quit"});
            return args;
        },
        600);
    ASSERT_NO_FATAL_FAILURE(expect_whole_timedemo(run, "demo2.dem"));
    const std::string& out = run.result.out;
    // Loaded at start-up, at frame 700 and after classic at 1000.
    EXPECT_EQ(lines_containing(out, "renderer: illustrative").size(), 3u) << out;
    EXPECT_EQ(lines_containing(out, "renderer: technical").size(), 1u) << out;
    EXPECT_TRUE(lines_containing(out, "keeping").empty()) << out;
}

TEST(IllustrativeDemo, ThePausedFrameShowsTheStylesModelsAndTermsOnTheirOwn) {
    const SharedRun& run = demo_illustrative();
    const RgbImage styled = load(run, "illustrative"), classic = load(run, "classic");
    const RgbImage albedo = load(run, "albedo"), view_dependent = load(run, "view_dependent");
    const RgbImage technical = load(run, "technical");
    ASSERT_GT(styled.width, 0);
    const size_t pixels = static_cast<size_t>(styled.width) * styled.height;
    // The monster gallery covers a good part of the frame; the style redraws it.
    const size_t changed = differing_pixels(styled, classic, 6);
    EXPECT_GT(changed, pixels / 20);
    EXPECT_GT(differing_pixels(styled, technical, 6), pixels / 20);
    // ill_show changes only the models: the world is the same in every picture, so a term shown
    // alone differs from the final picture on fewer pixels than the models cover in all.
    const size_t albedo_changed = differing_pixels(albedo, styled, 6);
    EXPECT_GT(albedo_changed, pixels / 40);
    EXPECT_LT(albedo_changed, changed + pixels / 10);
    // The view-dependent terms are highlights and rims: dark on most of each model.
    const RegionStats highlights = region_stats(view_dependent, whole(view_dependent));
    const RegionStats final_stats = region_stats(styled, whole(styled));
    EXPECT_LT(highlights.mean_luminance, final_stats.mean_luminance);
}

}  // namespace
}  // namespace nq

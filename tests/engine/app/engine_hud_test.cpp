// The status bar in the running engine: `timedemo demo` at 320x240 with the default
// viewsize (100), paused on one frame and screenshotted with the bars and again at
// viewsize 120. The bottom rows show the player's health, armour and ammo as gfx.wad's big
// digits, pixel for pixel where Quake puts them (the values come from replaying the demo
// in-process); everything above the bars is the same 3D view in both shots, because the
// bars are drawn over the view rather than shrinking it.
#include <gtest/gtest.h>

#include <string>

#include "support/engine_demo_replay.h"
#include "support/engine_image_checks.h"
#include "support/engine_output_checks.h"
#include "support/engine_runs.h"
#include "support/hud_test_support.h"

namespace nq {
namespace {

using test::engine_runs::kHeight;
using test::engine_runs::kWidth;

constexpr uint64_t kFrame = 301;  // standing still in the start room (docs/benchmarks.md)

const test::SharedRun& hud_run() {
    return test::shared_nprquake_run("demo_hud", [](const std::string& dir) {
        auto args = test::engine_runs::base_args(dir, test::data_root(), "lq1");
        test::engine_runs::add(args, {"+scr_drawhud", "1", "+gl_polyblend", "1"});
        test::engine_runs::demo_at(args, kFrame,
                                   "pause 1; wait; wait; screenshot " + dir +
                                       "/bars.png; viewsize 120; wait; wait; screenshot " + dir +
                                       "/none.png; quit");
        test::engine_runs::add(args, {"+timedemo", "demo", "+quit"});
        return args;
    });
}

// Opaque pixels of big digit picture `name` at (left, top) that differ from its colours.
int digit_mismatches(const RgbImage& shot, const Wad& wad, const Palette& palette,
                     const std::string& name, int left, int top) {
    Pic pic = test::wad_picture(wad, name);
    int mismatches = 0;
    for (int y = 0; y < pic.height; ++y) {
        for (int x = 0; x < pic.width; ++x) {
            uint8_t index = pic.at(x, y);
            if (index == kTransparentIndex) continue;
            const nq::Rgb& c = palette.colors[index];
            mismatches +=
                !test::near_colour(test::pixel(shot, left + x, top + y), {c.r, c.g, c.b}, 1);
        }
    }
    return mismatches;
}

// The digit pictures of `value` in a three-place field from x `field` (Quake's layout),
// each checked against the screenshot; returns how many digits matched.
int matching_digits(const RgbImage& shot, const Wad& wad, const Palette& palette, int value,
                    bool red, int field, int top) {
    std::string text = std::to_string(std::min(value, 999));
    int x = field + (3 - static_cast<int>(text.size())) * 24;
    int matched = 0;
    for (char c : text) {
        std::string name =
            std::string(red ? "anum_" : "num_") + (c == '-' ? "minus" : std::string(1, c));
        matched += digit_mismatches(shot, wad, palette, name, x, top) == 0;
        x += 24;
    }
    return matched;
}

TEST(EngineHud, BottomRowsShowTheStatusBarOverAnUnshrunkView) {
    const test::SharedRun& run = hud_run();
    test::expect_clean_exit(run.result);
    RgbImage bars, none;
    ASSERT_NO_FATAL_FAILURE(test::load_screenshot(run.dir + "/bars.png", bars));
    ASSERT_NO_FATAL_FAILURE(test::load_screenshot(run.dir + "/none.png", none));
    ASSERT_EQ(bars.width, kWidth);
    ASSERT_EQ(bars.height, kHeight);

    Vfs vfs = test::mount_lq1();
    test::DemoReplay replay(vfs, "demo.dem");
    ASSERT_TRUE(replay.play_to(kFrame));
    const PlayerState& player = replay.client().player();
    int health = player.stats[kStatHealth], armor = player.stats[kStatArmor];
    int ammo = player.stats[kStatAmmo];
    ASSERT_GT(health, 0) << "the check expects the status bar, not the dead player's scores";
    ASSERT_EQ(player.items & kItemInvulnerability, 0);

    test::HudTestData data;
    const int bar_top = kHeight - 24;  // 320 wide: scale 1, the bar from x 0
    auto digits = [](int v) { return static_cast<int>(std::to_string(std::min(v, 999)).size()); };
    EXPECT_EQ(matching_digits(bars, data.wad, data.palette, health, health <= 25, 136, bar_top),
              digits(health));
    EXPECT_EQ(matching_digits(bars, data.wad, data.palette, armor, armor <= 25, 24, bar_top),
              digits(armor));
    EXPECT_EQ(matching_digits(bars, data.wad, data.palette, ammo, ammo <= 10, 248, bar_top),
              digits(ammo));
    // Without the bars, the same places show no digits.
    EXPECT_EQ(matching_digits(none, data.wad, data.palette, health, health <= 25, 136, bar_top), 0);

    // The bars (status bar and inventory) cover the bottom 48 rows; above them the two shots
    // are the same picture.
    size_t differing_above = 0, differing_bars = 0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            bool differs = test::pixel(bars, x, y) != test::pixel(none, x, y);
            (y < kHeight - 48 ? differing_above : differing_bars) += differs;
        }
    }
    EXPECT_EQ(differing_above, 0u);
    EXPECT_GT(differing_bars, static_cast<size_t>(kWidth * 48 * 9 / 10));
}

}  // namespace
}  // namespace nq

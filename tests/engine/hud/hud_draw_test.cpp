// The engine's screen overlays drawn for real (offscreen GL, pixels read back): the status
// bar's digits are gfx.wad's num_* / anum_* pictures, pixel for pixel, where Quake puts them;
// viewsize decides how many bottom rows the bars cover; the damage flash tints the screen and
// fades to nothing; liquids tint it; gl_polyblend 0 turns the tints off; the crosshair is
// conchars' '+'; missing pictures draw nothing and break nothing. Expected colours come from
// the pictures decoded straight from the WAD and from Quake's blend rules.
#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "client/view.h"
#include "host/host_core.h"
#include "hud/hud.h"
#include "support/hud_test_support.h"
#include "support/synth_wad.h"
#include "video/screenshot.h"
#include "support/video_test_support.h"

namespace nq {
namespace {

using namespace test;

constexpr Rgb kClear{40, 60, 80};
constexpr int kContentsEmpty = -1;  // BSP leaf contents: open air

Rgb pixel(const RgbImage& image, int x, int y) {
    size_t at = (static_cast<size_t>(y) * image.width + x) * 3;
    return Rgb{image.rgb[at], image.rgb[at + 1], image.rgb[at + 2]};
}

bool near(Rgb a, Rgb b, int tolerance) {
    return std::abs(a.r - b.r) <= tolerance && std::abs(a.g - b.g) <= tolerance &&
           std::abs(a.b - b.b) <= tolerance;
}

// `over` at `alpha` on top of `under`, as the blend unit computes it.
Rgb blended(std::array<float, 3> over, float alpha, Rgb under) {
    auto mix = [&](float o, uint8_t u) {
        return static_cast<uint8_t>(std::lround(o * alpha + u * (1 - alpha)));
    };
    return Rgb{mix(over[0], under.r), mix(over[1], under.g), mix(over[2], under.b)};
}

// Rows [top, bottom) in which some pixel differs from kClear.
int changed_pixels(const RgbImage& image, int top, int bottom) {
    int count = 0;
    for (int y = top; y < bottom; ++y)
        for (int x = 0; x < image.width; ++x) count += !(pixel(image, x, y) == kClear);
    return count;
}

class HudDrawing : public ::testing::Test {
  protected:
    void make(int width, int height, bool with_pictures = true) {
        auto created = make_offscreen_window(width, height);
        ASSERT_TRUE(created) << created.error().message;
        window.emplace(std::move(*created));
        width_ = width;
        height_ = height;
        host.emplace();
        hud.emplace(*host);
        std::vector<std::string> messages =
            with_pictures ? hud->load_pictures(&data.wad, &data.palette, nullptr)
                          : hud->load_pictures(nullptr, nullptr, nullptr);
        ASSERT_NE(hud->drawer(), nullptr);
        for (const std::string& m : messages) {
            EXPECT_EQ(m.find("pictures not in the game data"), 0u) << m;  // only the .lmps
        }
        enter_level(client);
    }
    void TearDown() override {
        hud.reset();
        host.reset();
        window.reset();
    }
    void set(const char* cvar, const char* value) {
        ASSERT_TRUE(set_accepted(host->cvars().set(cvar, value))) << cvar;
    }
    RgbImage draw(int eye_contents = -1) {
        glClearColor(kClear.r / 255.0f, kClear.g / 255.0f, kClear.b / 255.0f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        hud->draw(client, eye_contents, width_, height_, 0.0);
        auto image = read_framebuffer_rgb(0, width_, height_);
        EXPECT_TRUE(image) << image.error().message;
        return image ? std::move(*image) : RgbImage{};
    }
    void player(int health, int armor, int ammo, int32_t items) {
        ASSERT_FALSE(client.apply(player_data(health, armor, ammo, items)));
    }
    // How many opaque pixels of wad picture `name` drawn with its top-left at (left, top)
    // differ from the picture's own colours (by more than `tolerance`); also counts them.
    int picture_mismatches(const RgbImage& image, const std::string& name, int left, int top,
                           int* opaque = nullptr, int tolerance = 1) {
        Pic pic = wad_picture(data.wad, name);
        int mismatches = 0, count = 0;
        for (int y = 0; y < pic.height; ++y) {
            for (int x = 0; x < pic.width; ++x) {
                uint8_t index = pic.at(x, y);
                if (index == kTransparentIndex) continue;
                ++count;
                mismatches +=
                    !near(pixel(image, left + x, top + y), data.palette.colors[index], tolerance);
            }
        }
        if (opaque) *opaque = count;
        return mismatches;
    }

    HudTestData data;
    std::optional<VideoWindow> window;
    std::optional<HostCore> host;
    std::optional<Hud> hud;
    ClientState client;
    int width_ = 0, height_ = 0;
};

TEST_F(HudDrawing, StatusBarDigitsAreTheWadsPicturesWhereQuakePutsThem) {
    make(320, 200);
    set("viewsize", "110");
    player(123, 0, 0, 0);
    RgbImage image = draw();
    // Health "123" in the field from x 136 of the bottom 24 rows.
    int opaque = 0;
    EXPECT_EQ(picture_mismatches(image, "num_1", 136, 176, &opaque), 0);
    EXPECT_GT(opaque, 50);
    EXPECT_EQ(picture_mismatches(image, "num_2", 160, 176), 0);
    EXPECT_EQ(picture_mismatches(image, "num_3", 184, 176), 0);
    // Not the red ones, which share the shapes.
    EXPECT_GT(picture_mismatches(image, "anum_2", 160, 176), 20);

    // Around the digits, the bar itself at scr_sbaralpha 0.75 over what was there.
    Pic sbar = wad_picture(data.wad, "sbar");
    Pic num_1 = wad_picture(data.wad, "num_1");
    int checked = 0;
    for (int y = 0; y < 24; ++y) {
        for (int x = 0; x < 24; ++x) {
            if (num_1.at(x, y) != kTransparentIndex) continue;
            Rgb bar = data.palette.colors[sbar.at(136 + x, y)];
            EXPECT_TRUE(near(pixel(image, 136 + x, 176 + y),
                             blended({float(bar.r), float(bar.g), float(bar.b)}, 0.75f, kClear), 2))
                << x << "," << y;
            ++checked;
        }
    }
    EXPECT_GT(checked, 100);
    // Nothing above the bar.
    EXPECT_EQ(changed_pixels(image, 0, 176), 0);
}

TEST_F(HudDrawing, LowHealthUsesTheRedDigits) {
    make(320, 200);
    set("viewsize", "110");
    player(7, 0, 0, 0);
    RgbImage image = draw();
    EXPECT_EQ(picture_mismatches(image, "anum_7", 184, 176), 0);
    EXPECT_GT(picture_mismatches(image, "num_7", 184, 176), 20);
}

TEST_F(HudDrawing, ViewsizeDecidesHowManyBottomRowsTheBarsCover) {
    make(640, 480);
    set("scr_sbarscale", "2");
    player(100, 100, 100, kItemShotgun | kItemShells | kItemArmor1);

    set("viewsize", "120");
    RgbImage none = draw();
    EXPECT_EQ(changed_pixels(none, 0, 480), 0) << "viewsize 120 leaves the view alone";
    EXPECT_EQ(hud->drawer()->draw_calls(), 0u);

    set("viewsize", "110");
    RgbImage bar = draw();
    EXPECT_EQ(changed_pixels(bar, 0, 480 - 48), 0);
    EXPECT_EQ(changed_pixels(bar, 480 - 48, 480), 640 * 48) << "the bar spans 320 x 2 pixels";
    EXPECT_EQ(hud->drawer()->draw_calls(), 1u) << "one atlas, one draw call";

    set("viewsize", "100");
    RgbImage both = draw();
    EXPECT_EQ(changed_pixels(both, 0, 480 - 96), 0);
    EXPECT_EQ(changed_pixels(both, 480 - 96, 480 - 48), 640 * 48) << "the inventory above it";
    // The status bar rows are the same as at 110.
    for (int y = 480 - 48; y < 480; y += 7) {
        for (int x = 0; x < 640; x += 5) EXPECT_TRUE(pixel(both, x, y) == pixel(bar, x, y));
    }
}

TEST_F(HudDrawing, DamageFlashTintsRedThenFadesToNothing) {
    make(160, 120);
    set("viewsize", "120");
    player(60, 0, 0, 0);
    svc::Damage hit;
    hit.blood = 100;  // count 50: shift 150, a second to fade
    ASSERT_FALSE(client.apply(hit));
    Rgb full = pixel(draw(), 80, 60);
    EXPECT_TRUE(near(full, blended({255, 0, 0}, 150.0f / 255, kClear), 2)) << int(full.r);
    client.set_time(client.time() + 0.5);
    Rgb half = pixel(draw(), 80, 60);
    EXPECT_TRUE(near(half, blended({255, 0, 0}, 75.0f / 255, kClear), 2)) << int(half.r);
    client.set_time(client.time() + 0.5);
    EXPECT_EQ(changed_pixels(draw(), 0, 120), 0);
}

TEST_F(HudDrawing, UnderwaterTintsTheViewAndPolyblendZeroTurnsTintsOff) {
    make(160, 120);
    set("viewsize", "120");
    player(100, 0, 0, 0);
    EXPECT_EQ(changed_pixels(draw(kContentsEmpty), 0, 120), 0);
    RgbImage water = draw(kContentsWater);
    Rgb expected = blended({130, 80, 50}, 128.0f / 255, kClear);
    EXPECT_TRUE(near(pixel(water, 0, 0), expected, 2));
    EXPECT_TRUE(near(pixel(water, 159, 119), expected, 2));
    EXPECT_TRUE(
        near(pixel(draw(kContentsLava), 80, 60), blended({255, 80, 0}, 150.0f / 255, kClear), 2));
    set("gl_polyblend", "0");
    EXPECT_EQ(changed_pixels(draw(kContentsWater), 0, 120), 0);
    ASSERT_FALSE(client.apply(player_data(100, 0, 0, kItemQuad)));
    EXPECT_EQ(changed_pixels(draw(kContentsWater), 0, 120), 0);
    set("gl_polyblend", "1");
    EXPECT_TRUE(near(pixel(draw(), 80, 60), blended({0, 0, 255}, 30.0f / 255, kClear), 2));
}

TEST_F(HudDrawing, DeadPlayersSeeTheScoresEvenAtViewsize120UnlessTheHudIsOff) {
    make(320, 200);
    set("viewsize", "120");
    player(0, 0, 0, 0);
    RgbImage dead = draw();
    EXPECT_EQ(changed_pixels(dead, 0, 176), 0);
    EXPECT_GT(changed_pixels(dead, 176, 200), 320 * 24 * 9 / 10) << "the scorebar, as Quake";
    set("scr_drawhud", "0");
    EXPECT_EQ(changed_pixels(draw(), 0, 200), 0);
    // The tints are gl_polyblend's business, not scr_drawhud's.
    EXPECT_TRUE(
        near(pixel(draw(kContentsWater), 5, 5), blended({130, 80, 50}, 128.0f / 255, kClear), 2));
}

TEST_F(HudDrawing, CrosshairIsConcharsPlusAtTheCentre) {
    make(160, 120);
    set("viewsize", "120");
    set("crosshair", "1");
    player(100, 0, 0, 0);
    RgbImage image = draw();
    Pic conchars = wad_picture(data.wad, "conchars");
    int cell_x = '+' % 16 * 8, cell_y = '+' / 16 * 8, ink = 0;
    for (int y = 0; y < 8; ++y) {
        for (int x = 0; x < 8; ++x) {
            uint8_t index = conchars.at(cell_x + x, cell_y + y);
            Rgb expected = index == 0 ? kClear : data.palette.colors[index];
            ink += index != 0;
            EXPECT_TRUE(pixel(image, 76 + x, 56 + y) == expected) << x << "," << y;
        }
    }
    EXPECT_GT(ink, 0);
    EXPECT_EQ(changed_pixels(image, 0, 56) + changed_pixels(image, 64, 120), 0);
}

TEST_F(HudDrawing, WithoutGameDataOnlyTheTintsAreDrawn) {
    make(160, 120, /*with_pictures=*/false);
    player(100, 50, 50, kItemShotgun);
    EXPECT_EQ(changed_pixels(draw(), 0, 120), 0);
    EXPECT_TRUE(
        near(pixel(draw(kContentsSlime), 10, 10), blended({0, 25, 5}, 150.0f / 255, kClear), 2));
}

TEST_F(HudDrawing, OnlyThePicturesTheDataHasAreDrawn) {
    make(320, 200, /*with_pictures=*/false);
    SynthWad synth;
    std::vector<uint8_t> red(320 * 24, 79);  // a dark red of the Quake palette
    synth.lumps.push_back({"SBAR", 0x42, 0, write_qpic(320, 24, red), {}, {}, {}});
    auto wad = parse_wad(write_wad(synth), "only_sbar.wad");
    ASSERT_TRUE(wad);
    hud->load_pictures(&*wad, &data.palette, nullptr);
    set("scr_sbaralpha", "1");
    player(100, 50, 50, kItemShotgun | kItemShells);
    RgbImage image = draw();
    EXPECT_EQ(changed_pixels(image, 0, 176), 0);
    Rgb bar = data.palette.colors[79];
    for (int x = 0; x < 320; x += 13) EXPECT_TRUE(pixel(image, x, 190) == bar) << x;
}

}  // namespace
}  // namespace nq

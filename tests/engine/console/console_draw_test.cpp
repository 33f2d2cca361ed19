// The console's fonts and drawing: the built-in font's glyphs, conchars through the palette,
// the quad batch, and pixels read back from an offscreen GL window.
#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <string>
#include <unordered_set>
#include <vector>

#include "common/file_io.h"
#include "console/console.h"
#include "console/console_drawer.h"
#include "console/console_font.h"
#include "console/console_scene.h"
#include "console/fallback_font_sheet.h"
#include "draw2d/quad_batch.h"
#include "formats/palette.h"
#include "formats/wad.h"
#include "host/host_core.h"
#include "support/synth_wad.h"
#include "support/test_data.h"
#include "video/screenshot.h"
#include "support/video_test_support.h"

namespace nq {
namespace {

constexpr uint8_t kInkIndex = 200;
constexpr Rgb kInk{10, 200, 30};
constexpr Rgb kClear{40, 60, 80};

// Alpha of pixel (x, y) of a 128x128 RGBA font image.
uint8_t alpha_at(const RgbaImage& image, int x, int y) {
    return image.rgba[(static_cast<size_t>(y) * image.width + x) * 4 + 3];
}

int ink_pixels(const RgbaImage& font, int glyph) {
    int count = 0;
    for (int y = 0; y < 8; ++y) {
        for (int x = 0; x < 8; ++x)
            count += alpha_at(font, glyph % 16 * 8 + x, glyph / 16 * 8 + y) > 0;
    }
    return count;
}

std::vector<uint8_t> glyph_bits(const RgbaImage& font, int glyph) {
    std::vector<uint8_t> bits;
    for (int y = 0; y < 8; ++y) {
        for (int x = 0; x < 8; ++x)
            bits.push_back(alpha_at(font, glyph % 16 * 8 + x, glyph / 16 * 8 + y) > 0);
    }
    return bits;
}

// Conchars indices with glyph 'H' a solid block of kInkIndex and everything else index 0.
std::vector<uint8_t> solid_h_conchars() {
    std::vector<uint8_t> pixels(128 * 128, 0);
    int cell_x = 'H' % 16 * 8, cell_y = 'H' / 16 * 8;
    for (int y = 0; y < 8; ++y) {
        for (int x = 0; x < 8; ++x)
            pixels[static_cast<size_t>(cell_y + y) * 128 + cell_x + x] = kInkIndex;
    }
    return pixels;
}

Palette ink_palette() {
    Palette palette;
    for (int i = 0; i < 256; ++i) palette.colors[i] = Rgb{uint8_t(i), uint8_t(i), uint8_t(i)};
    palette.colors[kInkIndex] = kInk;
    return palette;
}

TEST(FallbackFont, SheetIsWellFormed) {
    auto sheet = fallback_font_sheet();
    ASSERT_EQ(sheet.size(),
              static_cast<size_t>(kSheetGlyphCount / kSheetGlyphsPerRow * kSheetGlyphHeight));
    const size_t width = kSheetGlyphsPerRow * (kSheetGlyphWidth + 1) - 1;
    for (size_t row = 0; row < sheet.size(); ++row) {
        std::string_view text = sheet[row];
        ASSERT_EQ(text.size(), width) << "row " << row;
        for (size_t i = 0; i < text.size(); ++i) {
            bool separator = i % (kSheetGlyphWidth + 1) == kSheetGlyphWidth;
            EXPECT_EQ(separator, text[i] == ' ') << "row " << row << " column " << i;
            if (!separator) {
                EXPECT_TRUE(text[i] == '.' || text[i] == '#') << "row " << row;
            }
        }
    }
}

TEST(FallbackFont, EveryPrintableCharacterHasItsOwnGlyph) {
    const RgbaImage& font = fallback_font();
    ASSERT_EQ(font.width, 128);
    ASSERT_EQ(font.height, 128);
    // Shapes as strings in a hash set: GCC 12 warns (-Wstringop-overread, a false positive)
    // on std::set<std::vector<uint8_t>>'s ordering.
    std::unordered_set<std::string> shapes;
    for (int c = '!'; c <= '~'; ++c) {
        EXPECT_GT(ink_pixels(font, c), 0) << "'" << char(c) << "'";
        EXPECT_GT(ink_pixels(font, c + 128), 0) << "alternate '" << char(c) << "'";
        const std::vector<uint8_t> bits = glyph_bits(font, c);
        shapes.emplace(bits.begin(), bits.end());
    }
    EXPECT_EQ(shapes.size(), 94u) << "two printable characters share a glyph";
    EXPECT_EQ(ink_pixels(font, ' '), 0);
    for (int c = 0; c < 32; ++c) EXPECT_EQ(ink_pixels(font, c), 0) << c;
    // Same shapes, different colour in the alternate half.
    EXPECT_EQ(glyph_bits(font, 'A'), glyph_bits(font, 'A' + 128));
    size_t a = ('A' / 16 * 8 * 128 + 'A' % 16 * 8) * 4;
    size_t alt = (('A' + 128) / 16 * 8 * 128 + ('A' + 128) % 16 * 8) * 4;
    bool any_differs = false;
    for (int y = 0; y < 8; ++y) {
        for (int x = 0; x < 8; ++x) {
            size_t offset = (static_cast<size_t>(y) * 128 + x) * 4;
            if (font.rgba[a + offset + 3] == 0) continue;
            any_differs |= font.rgba[a + offset] != font.rgba[alt + offset] ||
                           font.rgba[a + offset + 2] != font.rgba[alt + offset + 2];
        }
    }
    EXPECT_TRUE(any_differs);
}

TEST(ConcharsFont, PaletteColoursAndTransparentZero) {
    std::vector<uint8_t> pixels = solid_h_conchars();
    pixels[5] = 7;
    auto font = conchars_to_rgba(pixels, ink_palette());
    ASSERT_TRUE(font) << font.error().message;
    EXPECT_EQ(alpha_at(*font, 0, 0), 0);  // index 0
    EXPECT_EQ(alpha_at(*font, 5, 0), 255);
    EXPECT_EQ(font->rgba[5 * 4], 7);
    size_t h = (static_cast<size_t>('H' / 16 * 8) * 128 + 'H' % 16 * 8) * 4;
    EXPECT_EQ(font->rgba[h + 0], kInk.r);
    EXPECT_EQ(font->rgba[h + 1], kInk.g);
    EXPECT_EQ(font->rgba[h + 2], kInk.b);
    EXPECT_EQ(font->rgba[h + 3], 255);

    auto wrong = conchars_to_rgba(std::vector<uint8_t>(100), ink_palette());
    ASSERT_FALSE(wrong);
    EXPECT_NE(wrong.error().message.find("16384"), std::string::npos) << wrong.error().message;
}

TEST(ConcharsFont, LoadsFromASyntheticWad) {
    test::SynthWad synth;
    synth.lumps.push_back({"CONCHARS", 0x44, 0, solid_h_conchars(), {}, {}, {}});
    auto wad = parse_wad(test::write_wad(synth), "synth.wad");
    ASSERT_TRUE(wad) << wad.error().message;
    auto font = load_conchars_font(*wad, ink_palette());
    ASSERT_TRUE(font) << font.error().message;
    EXPECT_EQ(ink_pixels(*font, 'H'), 64);
    EXPECT_EQ(ink_pixels(*font, 'E'), 0);

    test::SynthWad empty;
    empty.lumps.push_back({"OTHER", 0x42, 0, test::write_qpic(1, 1, {3}), {}, {}, {}});
    auto no_font = load_conchars_font(*parse_wad(test::write_wad(empty), "e.wad"), ink_palette());
    ASSERT_FALSE(no_font);
    EXPECT_NE(no_font.error().message.find("conchars"), std::string::npos);
}

TEST(ConcharsFont, LoadsLibreQuakeGfxWad) {
    auto wad_bytes = read_file(test::lq1_dir() + "/gfx.wad");
    ASSERT_TRUE(wad_bytes) << wad_bytes.error().message;
    auto palette_bytes = read_file(test::lq1_dir() + "/gfx/palette.lmp");
    ASSERT_TRUE(palette_bytes) << palette_bytes.error().message;
    auto wad = parse_wad(*wad_bytes, "gfx.wad");
    ASSERT_TRUE(wad) << wad.error().message;
    auto palette = parse_palette(*palette_bytes, "palette.lmp");
    ASSERT_TRUE(palette) << palette.error().message;
    auto font = load_conchars_font(*wad, *palette);
    ASSERT_TRUE(font) << font.error().message;
    EXPECT_EQ(font->width, 128);
    for (int c = 'A'; c <= 'Z'; ++c) EXPECT_GT(ink_pixels(*font, c), 0) << char(c);
    EXPECT_EQ(ink_pixels(*font, ' '), 0);
}

TEST(QuadBatch, FlushesWhenFullAndPlacesGlyphs) {
    QuadBatch batch(2);
    std::vector<size_t> flushed;
    batch.set_flush([&](std::span<const QuadVertex> v) { flushed.push_back(v.size() / 4); });
    batch.glyph('H', 10, 20, 8, Colour{});
    const QuadVertex& first = batch.vertices()[0];
    EXPECT_FLOAT_EQ(first.u, 8.0f / 16);  // 'H' = 72: column 8, row 4
    EXPECT_FLOAT_EQ(first.v, 4.0f / 16);
    EXPECT_FLOAT_EQ(batch.vertices()[2].x, 18.0f);
    EXPECT_FLOAT_EQ(batch.vertices()[2].y, 28.0f);
    EXPECT_EQ(first.sampling, kSampleTexelExact);
    batch.text("a b c", 0, 0, 8, Colour{});  // spaces add no quad: 4 quads so far
    batch.solid(0, 0, 1, 1, Colour{});       // the fifth
    EXPECT_EQ(flushed, (std::vector<size_t>{2, 2}));
    EXPECT_EQ(batch.quad_count(), 1u);
    EXPECT_EQ(batch.vertices()[0].sampling, kSampleNone);  // the solid quad
    batch.flush();
    EXPECT_EQ(flushed, (std::vector<size_t>{2, 2, 1}));
    EXPECT_EQ(batch.quad_count(), 0u);
}

// One glyph quad the scene emitted: which glyph, where (in cells, from the top-left pixel).
struct PlacedGlyph {
    char glyph;
    int column, row;
    friend bool operator==(const PlacedGlyph&, const PlacedGlyph&) = default;
};

// Runs the scene for `console` and decodes its textured quads back into glyphs.
std::vector<PlacedGlyph> scene_glyphs(const Console& console) {
    QuadBatch batch;
    std::vector<PlacedGlyph> glyphs;
    batch.set_flush([&](std::span<const QuadVertex> vertices) {
        int cell = console.layout().cell;
        for (size_t i = 0; i < vertices.size(); i += 4) {
            const QuadVertex& v = vertices[i];
            if (v.sampling == kSampleNone) continue;
            int index = static_cast<int>(v.v * 16 + 0.5f) * 16 + static_cast<int>(v.u * 16 + 0.5f);
            glyphs.push_back({static_cast<char>(index), static_cast<int>(v.x) / cell,
                              static_cast<int>(v.y) / cell});
        }
    });
    ConsoleScene scene;
    scene.build(console, batch, true);
    batch.flush();
    return glyphs;
}

TEST(ConsoleScene, InputLineScrollsSidewaysToKeepTheCursorVisible) {
    HostCore host;
    Console console(host);
    host.cvars().set("scr_conspeed", "0");
    console.set_screen_size(64, 160);  // 8 cells wide: 6 columns between the margins
    console.set_open(true);
    console.update(0.3);  // cursor off
    console.input().line().insert("abcdefghij");
    // Input row: 80 - 16 = 64, cell row 8. The cursor (column 11 of "]abcdefghij") must be on
    // screen, so the row shows columns 6..11: "fghij" and the cursor cell.
    std::vector<PlacedGlyph> expected;
    for (int i = 0; i < 5; ++i) expected.push_back({static_cast<char>('f' + i), 1 + i, 8});
    EXPECT_EQ(scene_glyphs(console), expected);

    console.input().line().move_home();  // back to the start: prompt and "abcde"
    expected = {{']', 1, 8}};
    for (int i = 0; i < 5; ++i) expected.push_back({static_cast<char>('a' + i), 2 + i, 8});
    EXPECT_EQ(scene_glyphs(console), expected);
}

TEST(ConsoleScene, ScrolledBackShowsMarkersAboveTheInputLine) {
    HostCore host;
    Console console(host);
    host.cvars().set("scr_conspeed", "0");
    console.set_screen_size(64, 160);
    console.set_open(true);
    console.update(0.3);
    for (const char* line : {"1\n", "2\n", "3\n", "4\n"}) console.print(line);
    console.text().scroll(1);
    // Console 80 tall: newest text row at 80 - 16 - 12 = 52 (cell row 6, pixel 52); with the
    // view scrolled back, that slot holds "^" every 4 columns and "3" moves one row up.
    std::vector<PlacedGlyph> glyphs = scene_glyphs(console);
    EXPECT_NE(std::find(glyphs.begin(), glyphs.end(), PlacedGlyph{'^', 1, 6}), glyphs.end());
    EXPECT_NE(std::find(glyphs.begin(), glyphs.end(), PlacedGlyph{'^', 5, 6}), glyphs.end());
    EXPECT_NE(std::find(glyphs.begin(), glyphs.end(), PlacedGlyph{'3', 1, 5}), glyphs.end());
    EXPECT_EQ(std::find_if(glyphs.begin(), glyphs.end(), [](auto& g) { return g.glyph == '4'; }),
              glyphs.end());
}

// A hidden window, a console on a host, a drawer, and helpers to read pixels back.
class ConsoleDrawing : public ::testing::Test {
  protected:
    void make(int width, int height) {
        auto created = test::make_offscreen_window(width, height);
        ASSERT_TRUE(created) << created.error().message;
        window.emplace(std::move(*created));
        width_ = width;
        height_ = height;
        host.emplace();
        host->set_print([this](std::string_view text) { console->print(text); });
        console.emplace(*host);
        host->cvars().set("scr_conspeed", "0");
        console->set_screen_size(width, height);
        auto made = ConsoleDrawer::create();
        ASSERT_TRUE(made) << made.error().message;
        drawer.emplace(std::move(*made));
    }
    void use_solid_h_font() {
        auto font = conchars_to_rgba(solid_h_conchars(), ink_palette());
        ASSERT_TRUE(font);
        drawer->set_font(*font);
    }
    void TearDown() override {
        drawer.reset();
        console.reset();
        host.reset();
        window.reset();
    }
    RgbImage draw() {
        glClearColor(kClear.r / 255.0f, kClear.g / 255.0f, kClear.b / 255.0f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        drawer->draw(*console);
        auto image = read_framebuffer_rgb(0, width_, height_);
        EXPECT_TRUE(image) << image.error().message;
        return image ? std::move(*image) : RgbImage{};
    }
    static Rgb pixel(const RgbImage& image, int x, int y) {
        size_t at = (static_cast<size_t>(y) * image.width + x) * 3;
        return Rgb{image.rgb[at], image.rgb[at + 1], image.rgb[at + 2]};
    }
    // Every pixel of the w x h block at (x, y) has `colour`.
    static bool block_is(const RgbImage& image, int x, int y, int w, int h, Rgb colour) {
        for (int j = y; j < y + h; ++j) {
            for (int i = x; i < x + w; ++i) {
                if (!(pixel(image, i, j) == colour)) return false;
            }
        }
        return true;
    }
    static int pixels_not(const RgbImage& image, int x, int y, int w, int h, Rgb colour) {
        int count = 0;
        for (int j = y; j < y + h; ++j) {
            for (int i = x; i < x + w; ++i) count += !(pixel(image, i, j) == colour);
        }
        return count;
    }

    std::optional<VideoWindow> window;
    std::optional<HostCore> host;
    std::optional<Console> console;
    std::optional<ConsoleDrawer> drawer;
    int width_ = 0, height_ = 0;
};

TEST_F(ConsoleDrawing, HelloInTheNotifyArea) {
    make(128, 96);
    use_solid_h_font();
    console->update(1.0);
    console->print("HELLO\n");
    RgbImage image = draw();
    // Notify rows start at the top, one cell in: 'H' fills x 8..15, y 0..7.
    EXPECT_TRUE(block_is(image, 8, 0, 8, 8, kInk));
    // E, L, L, O are empty glyphs in this font; nothing else is drawn.
    EXPECT_TRUE(block_is(image, 16, 0, 128 - 16, 8, kClear));
    EXPECT_TRUE(block_is(image, 0, 8, 128, 88, kClear));
    EXPECT_TRUE(block_is(image, 0, 0, 8, 8, kClear));
    EXPECT_EQ(drawer->quads_drawn(), 5u);
}

TEST_F(ConsoleDrawing, HelloOnTheInputLineOfTheOpenConsole) {
    make(128, 96);
    use_solid_h_font();
    console->set_open(true);
    console->update(0.3);  // cursor blinked off (4 flips per second): only the text
    console->input().line().insert("HELLO");
    RgbImage image = draw();
    // Console 48 pixels tall; the input line "]HELLO" sits at y 32..39, 'H' in column 2.
    EXPECT_TRUE(block_is(image, 16, 32, 8, 8, kInk));
    // The translucent background darkens the top half; the bottom half is untouched.
    Rgb background = pixel(image, 100, 10);
    EXPECT_LT(background.b, kClear.b);
    EXPECT_FALSE(background == kClear);
    EXPECT_TRUE(block_is(image, 0, 48, 128, 48, kClear));
}

TEST_F(ConsoleDrawing, CursorBlinks) {
    make(128, 96);
    console->set_open(true);
    console->update(0.0);
    RgbImage on = draw();
    console->update(0.3);
    RgbImage off = draw();
    // The cursor cell right after "]" (x 16..23, y 32..39) differs between the two phases.
    EXPECT_GT(pixels_not(on, 16, 32, 8, 8, pixel(off, 16, 32)), 0);
}

TEST_F(ConsoleDrawing, FallbackFontDrawsEveryPrintableCharacter) {
    make(800, 64);
    console->update(1.0);
    std::string all;
    for (char c = '!'; c <= '~'; ++c) all += c;
    ASSERT_LE(all.size(), console->text().columns());
    console->print(all + "\n");
    RgbImage image = draw();
    for (size_t i = 0; i < all.size(); ++i) {
        int x = 8 * static_cast<int>(i + 1);
        EXPECT_GT(pixels_not(image, x, 0, 8, 8, kClear), 0) << "'" << all[i] << "'";
    }
}

TEST_F(ConsoleDrawing, HiddenConsoleDrawsNothing) {
    make(128, 96);
    console->update(1.0);
    RgbImage image = draw();
    EXPECT_TRUE(block_is(image, 0, 0, 128, 96, kClear));
    EXPECT_EQ(drawer->draw_calls(), 0u);
    // Notify lines expire: printed at 1 s, gone after con_notifytime (3 s).
    console->print("HELLO\n");
    console->update(4.5);
    image = draw();
    EXPECT_TRUE(block_is(image, 0, 0, 128, 96, kClear));
    EXPECT_EQ(drawer->draw_calls(), 0u);
}

TEST_F(ConsoleDrawing, CenterPrintIsCentredAndExpires) {
    make(128, 96);
    use_solid_h_font();
    console->update(1.0);
    console->center_print("H");
    RgbImage image = draw();
    // x = (128 - 8) / 2 = 60; one short line starts 35% down: y = 33.
    EXPECT_TRUE(block_is(image, 60, 33, 8, 8, kInk));
    EXPECT_EQ(pixels_not(image, 0, 0, 128, 96, kClear), 64);
    console->update(3.0);  // scr_centertime 2
    image = draw();
    EXPECT_TRUE(block_is(image, 0, 0, 128, 96, kClear));
}

TEST_F(ConsoleDrawing, BackgroundPictureReplacesTheFill) {
    make(128, 96);
    RgbaImage red{2, 2, std::vector<uint8_t>(16, 0)};
    for (size_t i = 0; i < 16; i += 4) {
        red.rgba[i] = 255;
        red.rgba[i + 3] = 255;
    }
    drawer->set_background(red);
    console->set_open(true);
    console->update(0.3);
    RgbImage image = draw();
    EXPECT_TRUE(block_is(image, 0, 0, 128, 20, Rgb{255, 0, 0}));
    EXPECT_TRUE(block_is(image, 0, 48, 128, 48, kClear));
}

TEST_F(ConsoleDrawing, GlStateComesBack) {
    make(128, 96);
    console->set_open(true);
    console->update(0.0);
    glEnable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glViewport(3, 4, 50, 40);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);  // a wireframe renderer left this on
    RgbImage image = draw();
    // Drawn filled over the whole screen all the same: the top half is darkened throughout.
    EXPECT_EQ(pixels_not(image, 0, 0, 128, 40, kClear), 128 * 40);
    EXPECT_TRUE(glIsEnabled(GL_DEPTH_TEST));
    EXPECT_FALSE(glIsEnabled(GL_BLEND));
    GLint polygon_mode[2];
    glGetIntegerv(GL_POLYGON_MODE, polygon_mode);
    EXPECT_EQ(polygon_mode[0], GL_LINE);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    GLint viewport[4];
    glGetIntegerv(GL_VIEWPORT, viewport);
    EXPECT_EQ(viewport[0], 3);
    EXPECT_EQ(viewport[2], 50);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(ConsoleDrawing, ManyGlyphsFlushInSeveralDraws) {
    make(1024, 1024);
    host->cvars().set("con_scale", "1");
    console->update(0.0);
    console->set_open(true);
    console->update(0.0);
    std::string row(console->text().columns(), 'x');
    for (int i = 0; i < 100; ++i) console->print(row + "\n");
    draw();
    // 61 visible rows of 126 glyphs exceed one 4096-quad batch.
    EXPECT_GT(drawer->quads_drawn(), kQuadBatchCapacity);
    EXPECT_GE(drawer->draw_calls(), 2u);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

}  // namespace
}  // namespace nq

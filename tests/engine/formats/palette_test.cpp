// palette.lmp / colormap.lmp parsing and the player colour translation, against LibreQuake's
// files (facts checked in the data beforehand) and synthetic tables.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "formats/palette.h"
#include "support/raw_bytes.h"
#include "support/synth_wad.h"
#include "support/test_data.h"

namespace nq {
namespace {

using test::raw_file;

std::string gfx(const std::string& file) {
    return test::lq1_dir() + "/gfx/" + file;
}

double luminance(const Rgb& c) {
    return 0.299 * c.r + 0.587 * c.g + 0.114 * c.b;
}

Palette real_palette() {
    auto pal = parse_palette(raw_file(gfx("palette.lmp")), "palette.lmp");
    if (!pal) throw std::runtime_error(pal.error().to_string());
    return pal.value();
}

TEST(Palette, RealPaletteMatchesRawBytes) {
    const auto raw = raw_file(gfx("palette.lmp"));
    ASSERT_EQ(raw.size(), 768u);
    auto pal = parse_palette(raw, "palette.lmp");
    ASSERT_TRUE(pal) << pal.error().to_string();
    EXPECT_TRUE(pal->warnings.empty());
    for (size_t i = 0; i < 256; ++i) {
        EXPECT_EQ(pal->colors[i], (Rgb{raw[3 * i], raw[3 * i + 1], raw[3 * i + 2]})) << i;
    }
}

TEST(Palette, RealPaletteKnownColours) {
    const Palette pal = real_palette();
    EXPECT_EQ(pal.colors[0], (Rgb{0, 0, 0}));          // index 0 is black
    EXPECT_EQ(pal.colors[254], (Rgb{255, 255, 255}));  // brightest fullbright is white
    EXPECT_EQ(pal.colors[255], (Rgb{159, 91, 83}));    // the transparent "pink"
}

TEST(Palette, ShortPaletteIsAnErrorNamingTheSize) {
    auto bytes = test::synthetic_palette_lmp();
    bytes.resize(700);
    auto pal = parse_palette(bytes, "short.lmp");
    ASSERT_FALSE(pal);
    EXPECT_EQ(pal.error().file, "short.lmp");
    EXPECT_EQ(pal.error().offset, 0u);
    EXPECT_NE(pal.error().message.find("768"), std::string::npos) << pal.error().message;
    EXPECT_NE(pal.error().message.find("700"), std::string::npos) << pal.error().message;
}

TEST(Palette, TrailingBytesAreAWarning) {
    auto bytes = test::synthetic_palette_lmp();
    bytes.push_back(9);
    auto pal = parse_palette(bytes, "long.lmp");
    ASSERT_TRUE(pal) << pal.error().to_string();
    ASSERT_EQ(pal->warnings.size(), 1u);
    EXPECT_NE(pal->warnings[0].find("trailing"), std::string::npos);
    EXPECT_EQ(pal->colors[200], (Rgb{200, 55, 100}));
}

TEST(Colormap, RealColormapShape) {
    const auto raw = raw_file(gfx("colormap.lmp"));
    ASSERT_EQ(raw.size(), 64u * 256u);  // LibreQuake's has no trailing byte
    auto map = parse_colormap(raw, "colormap.lmp");
    ASSERT_TRUE(map) << map.error().to_string();
    EXPECT_TRUE(map->warnings.empty());
    ASSERT_EQ(map->table.size(), raw.size());
    EXPECT_EQ(map->shade(17, 93), raw[17 * 256 + 93]);
    EXPECT_EQ(map->row(40)[5], raw[40 * 256 + 5]);
}

TEST(Colormap, RealFullbrightsIgnoreLight) {
    auto map = parse_colormap(raw_file(gfx("colormap.lmp")), "colormap.lmp");
    ASSERT_TRUE(map) << map.error().to_string();
    for (int level = 0; level < kColormapLevels; ++level) {
        for (int i = kFirstFullbrightIndex; i <= kLastFullbrightIndex; ++i) {
            EXPECT_EQ(map->shade(level, uint8_t(i)), i) << "level " << level;
        }
        EXPECT_EQ(map->shade(level, 0), 0) << "black stays black at level " << level;
    }
}

TEST(Colormap, RealLevelsDarkenTowardsBlack) {
    auto map = parse_colormap(raw_file(gfx("colormap.lmp")), "colormap.lmp");
    ASSERT_TRUE(map) << map.error().to_string();
    const Palette pal = real_palette();
    double previous = 1e9;
    for (int level = 0; level < kColormapLevels; ++level) {
        double sum = 0;
        for (int i = 0; i < kFirstFullbrightIndex; ++i) {
            sum += luminance(pal.colors[map->shade(level, uint8_t(i))]);
        }
        EXPECT_LT(sum, previous) << "level " << level << " is not darker than the one before";
        previous = sum;
    }
    for (int i = 0; i < kFirstFullbrightIndex; ++i) EXPECT_EQ(map->shade(63, uint8_t(i)), 0);
}

TEST(Colormap, TruncatedIsAnError) {
    auto bytes = test::synthetic_colormap_lmp(false);
    bytes.resize(64 * 256 - 1);
    auto map = parse_colormap(bytes, "cm.lmp");
    ASSERT_FALSE(map);
    EXPECT_EQ(map.error().offset, 0u);
    EXPECT_NE(map.error().message.find("16384"), std::string::npos) << map.error().message;
}

TEST(Colormap, IdTrailingByteIsAWarning) {
    auto map = parse_colormap(test::synthetic_colormap_lmp(true), "cm.lmp");
    ASSERT_TRUE(map) << map.error().to_string();
    ASSERT_EQ(map->warnings.size(), 1u);
    EXPECT_NE(map->warnings[0].find("1 trailing byte"), std::string::npos) << map->warnings[0];
    EXPECT_EQ(map->shade(63, 100), 0);
    EXPECT_EQ(map->shade(0, 100), 100);
}

TEST(Fullbright, DocumentedRange) {
    EXPECT_FALSE(is_fullbright(223));
    EXPECT_TRUE(is_fullbright(224));
    EXPECT_TRUE(is_fullbright(254));
    EXPECT_FALSE(is_fullbright(255));  // transparent, not a colour
}

TEST(PlayerTranslation, IdentityOutsideTheRanges) {
    const auto t = player_translation(4, 11);
    for (int i = 0; i < 256; ++i) {
        const bool shirt = i >= 16 && i < 32;
        const bool pants = i >= 96 && i < 112;
        if (!shirt && !pants) {
            EXPECT_EQ(t[i], i);
        }
    }
}

TEST(PlayerTranslation, LowRowsCopyForwardHighRowsReversed) {
    const auto t = player_translation(4, 13);
    for (int j = 0; j < 16; ++j) {
        EXPECT_EQ(t[16 + j], 64 + j);        // row 4 is stored dark-to-light
        EXPECT_EQ(t[96 + j], 208 + 15 - j);  // row 13 is stored light-to-dark
    }
    const auto same = player_translation(1, 6);  // the default skin colours map to themselves
    for (int j = 0; j < 16; ++j) EXPECT_EQ(same[16 + j], 16 + j);
}

TEST(PlayerTranslation, ColoursAreClamped) {
    EXPECT_EQ(player_translation(-3, 0)[16], 0);
    EXPECT_EQ(player_translation(99, 0)[16], 255);  // row 15, reversed
}

TEST(PlayerTranslation, RealPaletteRampsRunDarkToLight) {
    const Palette pal = real_palette();
    for (int colour = 0; colour < 14; ++colour) {
        const auto t = player_translation(colour, colour);
        EXPECT_LT(luminance(pal.colors[t[16]]), luminance(pal.colors[t[31]])) << colour;
        EXPECT_LT(luminance(pal.colors[t[96]]), luminance(pal.colors[t[111]])) << colour;
    }
}

}  // namespace
}  // namespace nq

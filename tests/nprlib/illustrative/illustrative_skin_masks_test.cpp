// Derived skin masks: hand-picked entries of LibreQuake's palette (the same layout as Quake's)
// whose material classes are known from their bytes, and the RGBA8 image layout.
#include <gtest/gtest.h>

#include <cmath>

#include "common/file_io.h"
#include "illustrative/skin_masks.h"
#include "support/test_data.h"

namespace nq::npr::illustrative {
namespace {

std::vector<uint8_t> game_palette() {
    auto bytes = read_file(test::lq1_dir() + "/gfx/palette.lmp");
    if (!bytes || bytes->size() < 768) throw std::runtime_error("gfx/palette.lmp missing or short");
    return *bytes;
}

class IllustrativeSkinMasks : public ::testing::Test {
  protected:
    void SetUp() override {
        palette_ = game_palette();
        masks_ = derive_palette_masks(palette_.data());
    }
    const TexelMasks& at(int index) const { return masks_[size_t(index)]; }
    std::vector<uint8_t> palette_;
    PaletteMasks masks_{};
};

TEST_F(IllustrativeSkinMasks, PaletteBytesAreQuakes) {
    // The indices below were picked from these bytes.
    auto rgb = [&](int i) {
        return std::array<int, 3>{palette_[i * 3], palette_[i * 3 + 1], palette_[i * 3 + 2]};
    };
    EXPECT_EQ(rgb(15), (std::array<int, 3>{0xeb, 0xeb, 0xeb}));   // bright grey
    EXPECT_EQ(rgb(2), (std::array<int, 3>{0x1f, 0x1f, 0x1f}));    // dark grey
    EXPECT_EQ(rgb(47), (std::array<int, 3>{0x8b, 0x8b, 0xcb}));   // light blue-grey (steel)
    EXPECT_EQ(rgb(192), (std::array<int, 3>{0xff, 0xf3, 0x1b}));  // gold
    EXPECT_EQ(rgb(79), (std::array<int, 3>{0x7f, 0x00, 0x00}));   // blood red
    EXPECT_EQ(rgb(16), (std::array<int, 3>{0x0f, 0x0b, 0x07}));   // near-black brown
    EXPECT_EQ(rgb(160), (std::array<int, 3>{0xdb, 0xc3, 0xbb}));  // pale skin
    EXPECT_EQ(rgb(183), (std::array<int, 3>{0x37, 0x4b, 0x3f}));  // dark olive cloth
}

TEST_F(IllustrativeSkinMasks, MetalRowsAreShiny) {
    for (int i : {15, 47, 192}) {
        SCOPED_TRACE(i);
        EXPECT_TRUE(is_metal_palette_index(uint8_t(i)));
        EXPECT_GT(at(i).specular, 0.85f);
        EXPECT_GT(at(i).exponent, 90.0f);
        EXPECT_FLOAT_EQ(at(i).rim, 1.0f);
    }
    // Bright metal gets a tighter highlight than dark metal.
    EXPECT_GT(at(15).exponent, at(2).exponent);
    EXPECT_GT(at(15).specular, at(2).specular);
}

TEST_F(IllustrativeSkinMasks, ClothSkinAndBloodAreNearlyMatte) {
    for (int i : {79, 183, 16}) {
        SCOPED_TRACE(i);
        EXPECT_FALSE(is_metal_palette_index(uint8_t(i)));
        EXPECT_LT(at(i).specular, 0.1f);
        EXPECT_LT(at(i).exponent, 15.0f);
    }
    // Pure red has no "pale" part at all: the dielectric floor.
    EXPECT_NEAR(at(79).specular, 0.05f, 1e-6f);
    // Pale skin gets a soft sheen: above cloth, below metal.
    EXPECT_GT(at(160).specular, at(183).specular);
    EXPECT_LT(at(160).specular, at(15).specular);
    EXPECT_LT(at(160).exponent, at(15).exponent);
}

TEST_F(IllustrativeSkinMasks, RimFadesOnlyOnVeryDarkTexels) {
    EXPECT_LT(at(16).rim, 0.5f);  // near black
    EXPECT_GE(at(16).rim, 0.3f);
    EXPECT_FLOAT_EQ(at(160).rim, 1.0f);
    EXPECT_GT(at(79).rim, 0.9f);  // dark red still has luma 0.15
}

TEST_F(IllustrativeSkinMasks, FullbrightsAndTransparentHaveNoHighlight) {
    for (int i = 224; i <= 254; ++i) EXPECT_EQ(at(i).specular, 0.0f) << i;
    EXPECT_EQ(at(255).specular, 0.0f);
    EXPECT_EQ(at(255).rim, 0.0f);
}

TEST(IllustrativeSkinMaskCodec, ExponentRoundTrips) {
    EXPECT_FLOAT_EQ(encode_specular_exponent(kMinSpecularExponent), 0.0f);
    EXPECT_FLOAT_EQ(encode_specular_exponent(kMaxSpecularExponent), 1.0f);
    EXPECT_NEAR(decode_specular_exponent(encode_specular_exponent(40.0f)), 40.0f, 1e-4f);
    EXPECT_FLOAT_EQ(encode_specular_exponent(1000.0f), 1.0f);
}

TEST_F(IllustrativeSkinMasks, ImageIsRgba8InTexelOrder) {
    // 2 x 2 skin: bright grey, blood red / fullbright, near-black.
    const std::vector<uint8_t> skin = {15, 79, 250, 16};
    const std::vector<uint8_t> image = derive_skin_masks(skin, 2, 2, masks_);
    ASSERT_EQ(image.size(), 16u);
    auto byte = [](float v) { return int(std::lround(v * 255.0f)); };
    for (size_t t = 0; t < 4; ++t) {
        const TexelMasks& m = at(skin[t]);
        EXPECT_EQ(image[t * 4], byte(m.specular)) << t;
        EXPECT_EQ(image[t * 4 + 1], byte((m.exponent - 1.0f) / 149.0f)) << t;
        EXPECT_EQ(image[t * 4 + 2], byte(m.rim)) << t;
        EXPECT_EQ(image[t * 4 + 3], 255) << t;
    }
    EXPECT_GT(image[0], 200);  // grey metal: strong specular
    EXPECT_LT(image[4], 26);   // blood: weak
    EXPECT_EQ(image[8], 0);    // fullbright: none
    // A short pixel buffer never reads past its end; missing texels stay zero.
    const std::vector<uint8_t> partial = derive_skin_masks(std::vector<uint8_t>{15}, 2, 1, masks_);
    ASSERT_EQ(partial.size(), 8u);
    EXPECT_EQ(partial[7], 0);
}

}  // namespace
}  // namespace nq::npr::illustrative

// Light-warp ramps: the built-in ramps' shapes, resampling of user images, and PNG / .lmp
// decoding of untrusted bytes (errors name the file and the problem; nothing crashes).
#include <gtest/gtest.h>
#include <png.h>

#include <cmath>
#include <cstring>
#include <set>

#include "illustrative/ramp_image.h"
#include "illustrative/warp_ramp.h"

namespace nq::npr::illustrative {
namespace {

float luma(const glm::vec3& c) {
    return 0.299f * c.r + 0.587f * c.g + 0.114f * c.b;
}

// A palette where index k is (k, 255 - k, k / 2): every entry distinct and easy to predict.
std::vector<uint8_t> test_palette() {
    std::vector<uint8_t> p(768);
    for (int k = 0; k < 256; ++k) {
        p[k * 3] = uint8_t(k);
        p[k * 3 + 1] = uint8_t(255 - k);
        p[k * 3 + 2] = uint8_t(k / 2);
    }
    return p;
}

std::vector<uint8_t> lmp_bytes(int32_t width, int32_t height, const std::vector<uint8_t>& pixels) {
    std::vector<uint8_t> out;
    out.reserve(8 + pixels.size());  // GCC 12 -Warray-bounds false positive on insert otherwise
    out.resize(8);
    for (int i = 0; i < 4; ++i) {
        out[i] = uint8_t(uint32_t(width) >> (8 * i));
        out[4 + i] = uint8_t(uint32_t(height) >> (8 * i));
    }
    out.insert(out.end(), pixels.begin(), pixels.end());
    return out;
}

std::vector<uint8_t> png_bytes(int width, int height, const std::vector<uint8_t>& rgb) {
    png_image image;
    std::memset(&image, 0, sizeof image);
    image.version = PNG_IMAGE_VERSION;
    image.width = uint32_t(width);
    image.height = uint32_t(height);
    image.format = PNG_FORMAT_RGB;
    png_alloc_size_t size = 0;
    EXPECT_TRUE(png_image_write_to_memory(&image, nullptr, &size, 0, rgb.data(), 0, nullptr));
    std::vector<uint8_t> out(size);
    EXPECT_TRUE(png_image_write_to_memory(&image, out.data(), &size, 0, rgb.data(), 0, nullptr));
    out.resize(size);
    return out;
}

TEST(IllustrativeWarpRamp, Tf2ShadowIsCoolNotBlack) {
    const WarpRamp r = tf2_warp_ramp();
    const glm::vec3 back = r.rgb[0];
    EXPECT_GT(back.b, back.r);
    EXPECT_GT(back.b, back.g);
    EXPECT_GT(luma(back), 0.05f);  // x2 in the shader: clearly not black
    const glm::vec3 shadow = r.rgb[64];
    EXPECT_GT(shadow.b, shadow.r);
}

TEST(IllustrativeWarpRamp, Tf2TerminatorBandIsReddish) {
    const WarpRamp r = tf2_warp_ramp();
    const glm::vec3 mid = r.rgb[128];
    EXPECT_GT(mid.r, mid.g);
    EXPECT_GT(mid.r, mid.b);
    // Away from the band the red lean is gone.
    const glm::vec3 lit = r.rgb[200];
    EXPECT_LT(lit.r - lit.b, 0.5f * (mid.r - mid.b));
}

TEST(IllustrativeWarpRamp, Tf2LitSideIsGreyJustAboveMid) {
    const WarpRamp r = tf2_warp_ramp();
    const glm::vec3 top = r.rgb[255];
    EXPECT_NEAR(top.r, top.g, 0.01f);
    EXPECT_NEAR(top.g, top.b, 0.01f);
    EXPECT_GT(top.g, 0.5f);
    EXPECT_LT(top.g, 0.6f);
    // Brightness rises overall (small wiggles allowed where the tint changes).
    for (int i = 1; i < kWarpRampSize; ++i) EXPECT_GE(luma(r.rgb[i]), luma(r.rgb[i - 1]) - 0.01f);
    EXPECT_GT(luma(r.rgb[255]), luma(r.rgb[128]) + 0.2f);
}

TEST(IllustrativeWarpRamp, NeutralIsHalfLambertAsIs) {
    const WarpRamp r = neutral_warp_ramp();
    for (int i = 0; i < kWarpRampSize; ++i) {
        const float expected = float(i) / 255.0f * 0.5f;
        EXPECT_FLOAT_EQ(r.rgb[i].r, expected);
        EXPECT_FLOAT_EQ(r.rgb[i].g, expected);
        EXPECT_FLOAT_EQ(r.rgb[i].b, expected);
    }
}

TEST(IllustrativeWarpRamp, CelHasTwoOrThreeRisingBands) {
    const WarpRamp r = cel_warp_ramp();
    std::set<float> values;
    for (int i = 0; i < kWarpRampSize; ++i) {
        values.insert(r.rgb[i].g);
        if (i > 0) {
            EXPECT_GE(r.rgb[i].g, r.rgb[i - 1].g);
        }
    }
    EXPECT_GE(values.size(), 2u);
    EXPECT_LE(values.size(), 3u);
}

TEST(IllustrativeWarpRamp, BuiltinNamesAreCaseInsensitive) {
    EXPECT_TRUE(builtin_warp_ramp("tf2"));
    EXPECT_TRUE(builtin_warp_ramp("TF2"));
    EXPECT_TRUE(builtin_warp_ramp("Neutral"));
    EXPECT_TRUE(builtin_warp_ramp("cel"));
    EXPECT_FALSE(builtin_warp_ramp("gfx/ramp.png"));
    EXPECT_FALSE(builtin_warp_ramp(""));
}

TEST(IllustrativeWarpRamp, ToRgb8RoundsEachEntry) {
    const std::vector<uint8_t> bytes = neutral_warp_ramp().to_rgb8();
    ASSERT_EQ(bytes.size(), 768u);
    EXPECT_EQ(bytes[0], 0);
    EXPECT_EQ(bytes[255 * 3], 128);  // 0.5 * 255 = 127.5 rounds up
}

TEST(IllustrativeWarpRamp, TwoTexelImageGivesAStraightGradientFromItsMiddleRow) {
    // Three rows; only the middle one (black to white) may be used.
    RampImage image{2, 3, {255, 0, 0, 255, 0, 0, 0, 0, 0, 255, 255, 255, 0, 255, 0, 0, 255, 0}};
    const WarpRampResult r = ramp_from_image(image, "two.png");
    ASSERT_TRUE(r.ramp) << r.error;
    for (int i = 0; i < kWarpRampSize; ++i) {
        const float expected = float(i) / 255.0f;
        EXPECT_NEAR(r.ramp->rgb[i].r, expected, 1e-5f);
        EXPECT_NEAR(r.ramp->rgb[i].g, expected, 1e-5f);
        EXPECT_NEAR(r.ramp->rgb[i].b, expected, 1e-5f);
    }
}

TEST(IllustrativeWarpRamp, NarrowImageIsAnError) {
    const WarpRampResult r = ramp_from_image(RampImage{1, 1, {1, 2, 3}}, "thin.png");
    EXPECT_FALSE(r.ramp);
    EXPECT_NE(r.error.find("thin.png"), std::string::npos);
}

TEST(IllustrativeWarpRamp, LmpIsPaletteDecodedAndResampled) {
    const std::vector<uint8_t> palette = test_palette();
    // 4 x 1: indices 10, 20, 30, 40; the ramp's ends are exactly the first and last texel.
    const WarpRampResult r =
        decode_warp_ramp(lmp_bytes(4, 1, {10, 20, 30, 40}), "gfx/ramp.lmp", palette.data());
    ASSERT_TRUE(r.ramp) << r.error;
    EXPECT_NEAR(r.ramp->rgb[0].r, 10 / 255.0f, 1e-5f);
    EXPECT_NEAR(r.ramp->rgb[0].g, 245 / 255.0f, 1e-5f);
    EXPECT_NEAR(r.ramp->rgb[255].r, 40 / 255.0f, 1e-5f);
    EXPECT_NEAR(r.ramp->rgb[255].b, 20 / 255.0f, 1e-5f);
    // Entry 85 sits exactly on texel 1 (85 * 3 / 255 = 1).
    EXPECT_NEAR(r.ramp->rgb[85].r, 20 / 255.0f, 1e-5f);
}

TEST(IllustrativeWarpRamp, LmpErrorsNameFileAndProblem) {
    const std::vector<uint8_t> palette = test_palette();
    auto error_of = [&](const std::vector<uint8_t>& bytes) {
        const WarpRampResult r = decode_warp_ramp(bytes, "gfx/bad.lmp", palette.data());
        EXPECT_FALSE(r.ramp);
        EXPECT_NE(r.error.find("gfx/bad.lmp"), std::string::npos) << r.error;
        return r.error;
    };
    EXPECT_NE(error_of({1, 0, 0}).find("truncated"), std::string::npos);
    EXPECT_NE(error_of(lmp_bytes(4, 2, {1, 2, 3})).find("truncated"), std::string::npos);
    EXPECT_NE(error_of(lmp_bytes(-4, 1, {})).find("bad dimensions"), std::string::npos);
    EXPECT_NE(error_of(lmp_bytes(1, 1, {7})).find("bad dimensions"), std::string::npos);
    EXPECT_NE(error_of(lmp_bytes(100000, 100000, {})).find("huge"), std::string::npos);
    EXPECT_NE(error_of(lmp_bytes(4096, 4096, {})).find("huge"), std::string::npos);
    // Without the palette a .lmp cannot be decoded.
    const WarpRampResult r = decode_warp_ramp(lmp_bytes(2, 1, {1, 2}), "a.lmp", nullptr);
    EXPECT_NE(r.error.find("palette"), std::string::npos);
}

TEST(IllustrativeWarpRamp, PngRoundTrip) {
    // 3 x 3, middle row red -> green -> blue.
    std::vector<uint8_t> rgb(27, 77);
    const uint8_t middle[9] = {255, 0, 0, 0, 255, 0, 0, 0, 255};
    std::memcpy(&rgb[9], middle, 9);
    const WarpRampResult r = decode_warp_ramp(png_bytes(3, 3, rgb), "ramp.png", nullptr);
    ASSERT_TRUE(r.ramp) << r.error;
    EXPECT_NEAR(r.ramp->rgb[0].r, 1.0f, 1e-5f);
    EXPECT_NEAR(r.ramp->rgb[255].b, 1.0f, 1e-5f);
    // Halfway (entry 127.5 would be texel 1): entry 128 is just past pure green.
    EXPECT_NEAR(r.ramp->rgb[128].g, 1.0f - 1.0f / 255.0f, 1e-4f);
}

TEST(IllustrativeWarpRamp, CorruptPngIsAnErrorNotACrash) {
    std::vector<uint8_t> rgb(4 * 2 * 3, 100);
    const std::vector<uint8_t> good = png_bytes(4, 2, rgb);
    // Cut in the middle of the data.
    std::vector<uint8_t> cut(good.begin(), good.begin() + long(good.size() / 2));
    WarpRampResult r = decode_warp_ramp(cut, "cut.png", nullptr);
    EXPECT_FALSE(r.ramp);
    EXPECT_NE(r.error.find("cut.png"), std::string::npos);
    // Scramble everything after the signature.
    std::vector<uint8_t> scrambled = good;
    for (size_t i = 8; i < scrambled.size(); ++i) scrambled[i] ^= uint8_t(0x5a + i);
    r = decode_warp_ramp(scrambled, "scrambled.png", nullptr);
    EXPECT_FALSE(r.ramp);
    EXPECT_NE(r.error.find("scrambled.png"), std::string::npos);
    // A 1-pixel-wide PNG decodes but is no ramp.
    r = decode_warp_ramp(png_bytes(1, 4, std::vector<uint8_t>(12, 9)), "thin.png", nullptr);
    EXPECT_FALSE(r.ramp);
    EXPECT_NE(r.error.find("bad dimensions"), std::string::npos);
    // Neither signature nor extension.
    r = decode_warp_ramp(std::vector<uint8_t>{1, 2, 3}, "ramp.tga", nullptr);
    EXPECT_NE(r.error.find("ramp.tga"), std::string::npos);
}

TEST(IllustrativeWarpRamp, FindByNameOrPath) {
    const std::vector<uint8_t> palette = test_palette();
    const RampFileReader reader =
        [](const std::string& path) -> std::optional<std::vector<uint8_t>> {
        if (path == "gfx/ramp.lmp") return lmp_bytes(2, 1, {0, 255});
        return std::nullopt;
    };
    WarpRampResult r = find_warp_ramp("tf2", reader, palette.data());
    ASSERT_TRUE(r.ramp);
    EXPECT_EQ(r.ramp->rgb[255], tf2_warp_ramp().rgb[255]);
    r = find_warp_ramp("gfx/ramp.lmp", reader, palette.data());
    ASSERT_TRUE(r.ramp) << r.error;
    EXPECT_NEAR(r.ramp->rgb[255].r, 1.0f, 1e-6f);
    r = find_warp_ramp("gfx/missing.png", reader, palette.data());
    EXPECT_FALSE(r.ramp);
    EXPECT_NE(r.error.find("gfx/missing.png"), std::string::npos);
}

}  // namespace
}  // namespace nq::npr::illustrative

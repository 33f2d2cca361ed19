// World-texture abstraction: the Kuwahara filter keeps flat areas flat and edges sharp, removes
// noise, wraps around like a tiling texture; the colour boost saturates colours and leaves
// greys grey; and a big map's worth of textures is fast (measured here, bounded in optimised
// builds).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>

#include "illustrative/kuwahara_filter.h"
#include "illustrative/texture_abstraction.h"

namespace nq::npr::illustrative {
namespace {

struct Image {
    int width, height;
    std::vector<uint8_t> rgb;
    uint8_t* at(int x, int y) { return &rgb[(size_t(y) * size_t(width) + size_t(x)) * 3]; }
    const uint8_t* at(int x, int y) const {
        return &rgb[(size_t(y) * size_t(width) + size_t(x)) * 3];
    }
};

Image filled(int w, int h, uint8_t r, uint8_t g, uint8_t b) {
    Image im{w, h, std::vector<uint8_t>(size_t(w) * size_t(h) * 3)};
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            uint8_t* p = im.at(x, y);
            p[0] = r;
            p[1] = g;
            p[2] = b;
        }
    }
    return im;
}

// Deterministic noise (a small LCG), so a failure reproduces.
struct Lcg {
    uint32_t state;
    int next(int range) {
        state = state * 1664525u + 1013904223u;
        return int((state >> 8) % uint32_t(range));
    }
};

Image kuwahara(const Image& in, int radius) {
    Image out{in.width, in.height, {}};
    kuwahara_filter(in.rgb, in.width, in.height, radius, out.rgb);
    return out;
}

double grey_variance(const Image& im) {
    double sum = 0.0, sq = 0.0;
    const size_t n = im.rgb.size();
    for (uint8_t v : im.rgb) {
        sum += v;
        sq += double(v) * v;
    }
    const double mean = sum / double(n);
    return sq / double(n) - mean * mean;
}

float hsv_saturation(const uint8_t* p) {
    const float hi = std::max({p[0], p[1], p[2]}), lo = std::min({p[0], p[1], p[2]});
    return hi > 0.0f ? (hi - lo) / hi : 0.0f;
}

TEST(IllustrativeTextureAbstraction, ConstantImageStaysConstant) {
    const Image in = filled(16, 16, 90, 140, 30);
    EXPECT_EQ(kuwahara(in, 3).rgb, in.rgb);
    const std::vector<uint8_t> out = abstract_texture(in.rgb, 16, 16);
    ASSERT_EQ(out.size(), in.rgb.size());
    for (size_t i = 3; i < out.size(); ++i) EXPECT_EQ(out[i], out[i % 3]) << i;
}

TEST(IllustrativeTextureAbstraction, HardEdgeStaysSharp) {
    // Left half red-brown, right half blue-grey; the image wraps, so x = 0 | 31 is an edge too.
    Image in = filled(32, 16, 150, 60, 40);
    for (int y = 0; y < 16; ++y) {
        for (int x = 16; x < 32; ++x) {
            uint8_t* p = in.at(x, y);
            p[0] = 70;
            p[1] = 80;
            p[2] = 120;
        }
    }
    const Image out = kuwahara(in, 3);
    for (int y = 0; y < 16; ++y) {
        for (int x = 0; x < 32; ++x) {
            const int to_edge = std::min({std::abs(x - 16), std::abs(x - 15), x, 31 - x});
            if (to_edge < 2) continue;
            for (int c = 0; c < 3; ++c) ASSERT_EQ(out.at(x, y)[c], in.at(x, y)[c]) << x << "," << y;
        }
    }
}

TEST(IllustrativeTextureAbstraction, NoiseInAFlatRegionDrops) {
    Image in = filled(64, 64, 0, 0, 0);
    Lcg lcg{12345};
    for (uint8_t& v : in.rgb) v = uint8_t(128 - 30 + lcg.next(61));
    // Same noise on all three channels of a pixel would be fine too; independent is harder.
    const double before = grey_variance(in);
    const double after = grey_variance(kuwahara(in, 3));
    EXPECT_GT(before, 250.0);
    EXPECT_LT(after, before * 0.25) << before << " -> " << after;
}

TEST(IllustrativeTextureAbstraction, SaturationBoostKeepsGreysGrey) {
    std::vector<uint8_t> rgb = {200, 100, 50, 120, 120, 120, 30, 30, 30};
    const std::vector<uint8_t> before = rgb;
    boost_saturation_and_contrast(rgb, 1.5f, 1.0f);
    EXPECT_GT(hsv_saturation(&rgb[0]), hsv_saturation(&before[0]) + 0.05f);
    EXPECT_EQ(rgb[3], rgb[4]);
    EXPECT_EQ(rgb[4], rgb[5]);
    EXPECT_EQ(rgb[6], rgb[7]);
    EXPECT_EQ(rgb[7], rgb[8]);
    // Contrast 1: luma unchanged, so greys keep their value too.
    EXPECT_EQ(rgb[3], 120);
    EXPECT_EQ(rgb[6], 30);
}

TEST(IllustrativeTextureAbstraction, ContrastSpreadsValuesAroundTheMean) {
    std::vector<uint8_t> rgb = {100, 100, 100, 160, 160, 160};  // mean luma 130
    boost_saturation_and_contrast(rgb, 1.0f, 1.5f);
    EXPECT_EQ(rgb[0], 85);   // 130 + (100 - 130) * 1.5
    EXPECT_EQ(rgb[3], 175);  // 130 + (160 - 130) * 1.5
    std::vector<uint8_t> bright = {250, 250, 250, 10, 10, 10};
    boost_saturation_and_contrast(bright, 1.0f, 3.0f);  // clamps, never wraps
    EXPECT_EQ(bright[0], 255);
    EXPECT_EQ(bright[3], 0);
}

TEST(IllustrativeTextureAbstraction, WrapsLikeATilingTexture) {
    // Filtering a circularly shifted texture gives the shifted result: the neighbourhood of a
    // border texel is the opposite border, exactly as when the texture repeats on a wall.
    const int w = 24, h = 20, dx = 7, dy = 5;
    Image in = filled(w, h, 0, 0, 0);
    Lcg lcg{777};
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            uint8_t* p = in.at(x, y);
            const bool brick = ((x / 6) + (y / 5)) % 2 == 0;
            for (int c = 0; c < 3; ++c) p[c] = uint8_t((brick ? 160 : 60) + lcg.next(40));
        }
    }
    Image shifted = in;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            std::copy_n(in.at(x, y), 3, shifted.at((x + dx) % w, (y + dy) % h));
        }
    }
    const Image a = kuwahara(in, 2), b = kuwahara(shifted, 2);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            for (int c = 0; c < 3; ++c) {
                ASSERT_EQ(a.at(x, y)[c], b.at((x + dx) % w, (y + dy) % h)[c]) << x << "," << y;
            }
        }
    }
}

TEST(IllustrativeTextureAbstraction, TinyTextureBigRadius) {
    // A 16 x 16 texture with a radius larger than itself still works (wraps repeatedly).
    Image in = filled(16, 16, 10, 20, 30);
    in.at(3, 3)[0] = 250;
    const Image out = kuwahara(in, kMaxKuwaharaRadius + 10);
    ASSERT_EQ(out.rgb.size(), in.rgb.size());
    // Wrong sizes give nothing rather than reading past the buffer.
    std::vector<uint8_t> bad;
    kuwahara_filter(std::vector<uint8_t>(10), 4, 4, 2, bad);
    EXPECT_TRUE(bad.empty());
}

TEST(IllustrativeTextureAbstraction, RgbaKeepsAlpha) {
    std::vector<uint8_t> rgba(16 * 16 * 4, 100);
    for (size_t i = 3; i < rgba.size(); i += 4) rgba[i] = uint8_t(i % 2 ? 0 : 255);
    rgba[7] = 255;
    const std::vector<uint8_t> out = abstract_texture_rgba(rgba, 16, 16);
    ASSERT_EQ(out.size(), rgba.size());
    for (size_t i = 3; i < rgba.size(); i += 4) EXPECT_EQ(out[i], rgba[i]);
}

TEST(IllustrativeTextureAbstraction, HundredBigTexturesAreFast) {
    // A big map: ~100 textures, here all the largest size Quake uses, 256 x 256.
    // Sanitizer and debug builds run a tenth of them (they are ~30x slower; only timed).
#if defined(NDEBUG) && !defined(__SANITIZE_ADDRESS__)
    const int count = 100;
#else
    const int count = 10;
#endif
    std::vector<Image> textures;
    Lcg lcg{4242};
    for (int i = 0; i < count; ++i) {
        Image im = filled(256, 256, 0, 0, 0);
        for (uint8_t& v : im.rgb) v = uint8_t(lcg.next(256));
        textures.push_back(std::move(im));
    }
    // CPU time is what is bounded: on a machine shared with builds, wall time also counts
    // the time other processes had the core.
    const auto start = std::chrono::steady_clock::now();
    const std::clock_t cpu_start = std::clock();
    size_t checksum = 0;
    for (const Image& im : textures) checksum += abstract_texture(im.rgb, 256, 256)[0];
    const double cpu_ms = 1000.0 * double(std::clock() - cpu_start) / CLOCKS_PER_SEC;
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    std::printf(
        "abstract_texture: %d textures of 256x256 (radius 2): %.1f ms CPU, %.1f ms wall "
        "(checksum %zu)\n",
        count, cpu_ms, ms, checksum);
#if defined(NDEBUG) && !defined(__SANITIZE_ADDRESS__)
    EXPECT_LT(cpu_ms, 300.0);
#endif
}

}  // namespace
}  // namespace nq::npr::illustrative

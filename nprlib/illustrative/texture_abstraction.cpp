#include "illustrative/texture_abstraction.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "illustrative/kuwahara_filter.h"

namespace nq::npr::illustrative {
namespace {

float luma(float r, float g, float b) {
    return 0.299f * r + 0.587f * g + 0.114f * b;
}

float mean_luma(const uint8_t* rgb, size_t pixels) {
    // Integer sums of each channel: exact, and luma is linear so it can be taken at the end.
    uint64_t sum[3] = {0, 0, 0};
    for (size_t i = 0; i < pixels; ++i) {
        sum[0] += rgb[i * 3];
        sum[1] += rgb[i * 3 + 1];
        sum[2] += rgb[i * 3 + 2];
    }
    if (pixels == 0) return 0.0f;
    return luma(float(sum[0]), float(sum[1]), float(sum[2])) / float(pixels);
}

}  // namespace

void boost_saturation_and_contrast(std::vector<uint8_t>& rgb, float saturation, float contrast) {
    // Per channel c with pixel luma l and the texture's mean luma m:
    //   c' = l + (c - l) * saturation      push away from the pixel's own luma (a grey pixel
    //                                      has no distance to push, so it stays grey)
    //      + (l - m) * (contrast - 1)      move luma away from the texture's mean, the same
    //                                      shift on every channel so the hue is kept
    // which is linear: c' = offset + sum_i k * w_i * c_i + saturation * c, with luma weights
    // w_i and k = 1 - saturation + contrast - 1. So it runs on lookup tables in 1/256 steps.
    uint8_t* p = rgb.data();  // a raw pointer: uint8_t writes would alias the vector's members
    const size_t pixels = rgb.size() / 3;
    const float pivot = mean_luma(p, pixels);
    const float k = contrast - saturation;
    const float offset = -pivot * (contrast - 1.0f);
    constexpr float kWeights[3] = {0.299f, 0.587f, 0.114f};
    std::array<std::array<int32_t, 256>, 3> luma_part{};
    std::array<int32_t, 256> own_part{};
    for (int v = 0; v < 256; ++v) {
        for (int c = 0; c < 3; ++c) {
            luma_part[size_t(c)][size_t(v)] =
                int32_t(std::lround(k * kWeights[c] * float(v) * 256.0f));
        }
        own_part[size_t(v)] = int32_t(std::lround(saturation * float(v) * 256.0f));
    }
    const int32_t base0 = int32_t(std::lround(offset * 256.0f)) + 128;  // + 128: round
    for (size_t i = 0; i < pixels; ++i, p += 3) {
        const int32_t base = base0 + luma_part[0][p[0]] + luma_part[1][p[1]] + luma_part[2][p[2]];
        for (int c = 0; c < 3; ++c) {
            p[c] = uint8_t(std::clamp((base + own_part[p[c]]) >> 8, 0, 255));
        }
    }
}

std::vector<uint8_t> abstract_texture(std::span<const uint8_t> rgb, int width, int height,
                                      const AbstractionSettings& settings) {
    std::vector<uint8_t> out;
    kuwahara_filter(rgb, width, height, settings.radius, out);
    boost_saturation_and_contrast(out, settings.saturation, settings.contrast);
    return out;
}

std::vector<uint8_t> abstract_texture_rgba(std::span<const uint8_t> rgba, int width, int height,
                                           const AbstractionSettings& settings) {
    if (width <= 0 || height <= 0 || rgba.size() != size_t(width) * size_t(height) * 4) return {};
    const size_t pixels = size_t(width) * size_t(height);
    std::vector<uint8_t> rgb(pixels * 3);
    for (size_t i = 0; i < pixels; ++i) std::copy_n(&rgba[i * 4], 3, &rgb[i * 3]);
    const std::vector<uint8_t> done = abstract_texture(rgb, width, height, settings);
    std::vector<uint8_t> out(rgba.begin(), rgba.end());
    for (size_t i = 0; i < pixels; ++i) std::copy_n(&done[i * 3], 3, &out[i * 4]);
    return out;
}

}  // namespace nq::npr::illustrative

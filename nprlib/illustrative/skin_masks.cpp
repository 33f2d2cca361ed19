#include "illustrative/skin_masks.h"

#include <algorithm>
#include <cmath>

namespace nq::npr::illustrative {
namespace {

constexpr int kFirstFullbright = 224;
constexpr int kLastFullbright = 254;
constexpr int kTransparent = 255;

float smoothstep(float edge0, float edge1, float x) {
    const float t = std::clamp((x - edge0) / (edge1 - edge0), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

uint8_t to_byte(float v) {
    return uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
}

TexelMasks masks_of_colour(uint8_t index, const uint8_t* rgb) {
    const float r = rgb[0] / 255.0f, g = rgb[1] / 255.0f, b = rgb[2] / 255.0f;
    const float v = std::max({r, g, b});
    const float s = v > 0.0f ? (v - std::min({r, g, b})) / v : 0.0f;
    const float luma = 0.299f * r + 0.587f * g + 0.114f * b;
    TexelMasks m;
    if (is_metal_palette_index(index)) {
        m.specular = 0.35f + 0.65f * v;
        m.exponent = 20.0f + 130.0f * v;
    } else {
        const float pale = v * (1.0f - s);
        m.specular = 0.05f + 0.45f * std::pow(pale, 1.5f);
        m.exponent = 4.0f + 26.0f * pale;
    }
    m.rim = 0.3f + 0.7f * smoothstep(0.0f, 0.15f, luma);
    return m;
}

}  // namespace

bool is_metal_palette_index(uint8_t index) {
    const int row = index / 16;
    return row == 0 || row == 2 || row == 5 || row == 12;
}

PaletteMasks derive_palette_masks(const uint8_t* palette) {
    PaletteMasks out{};
    for (int i = 0; i < 256; ++i) {
        TexelMasks& m = out[size_t(i)];
        if (i >= kFirstFullbright && i <= kLastFullbright) {
            m = {0.0f, kMinSpecularExponent, 1.0f};
        } else if (i == kTransparent) {
            m = {0.0f, kMinSpecularExponent, 0.0f};
        } else {
            m = masks_of_colour(uint8_t(i), palette + size_t(i) * 3);
        }
    }
    return out;
}

float encode_specular_exponent(float exponent) {
    return std::clamp(
        (exponent - kMinSpecularExponent) / (kMaxSpecularExponent - kMinSpecularExponent), 0.0f,
        1.0f);
}

float decode_specular_exponent(float encoded) {
    return kMinSpecularExponent +
           std::clamp(encoded, 0.0f, 1.0f) * (kMaxSpecularExponent - kMinSpecularExponent);
}

std::vector<uint8_t> derive_skin_masks(std::span<const uint8_t> pixels, int width, int height,
                                       const PaletteMasks& masks) {
    const size_t count = size_t(std::max(width, 0)) * size_t(std::max(height, 0));
    // One RGBA8 texel per palette index, then a table lookup per skin texel.
    std::array<std::array<uint8_t, 4>, 256> texel{};
    for (size_t i = 0; i < 256; ++i) {
        texel[i] = {to_byte(masks[i].specular),
                    to_byte(encode_specular_exponent(masks[i].exponent)), to_byte(masks[i].rim),
                    255};
    }
    std::vector<uint8_t> out(count * 4, 0);
    const size_t n = std::min(count, pixels.size());
    for (size_t i = 0; i < n; ++i) std::copy_n(texel[pixels[i]].data(), 4, &out[i * 4]);
    return out;
}

}  // namespace nq::npr::illustrative

#include "illustrative/warp_ramp.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include <glm/common.hpp>

#include "illustrative/ramp_image.h"

namespace nq::npr::illustrative {
namespace {

// x of entry i: 0 at the first entry, 1 at the last.
float entry_x(int i) {
    return float(i) / float(kWarpRampSize - 1);
}

float smoothstep(float edge0, float edge1, float x) {
    const float t = std::clamp((x - edge0) / (edge1 - edge0), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

// The tf2 ramp's brightness: from 0.12 (x2 = 0.24, dark but not black) at the back, through
// 0.27 at the terminator, to 0.55 (x2 = 1.1, a little overbright) facing the light.
float tf2_value(float x) {
    if (x < 0.5f) return 0.12f + (0.27f - 0.12f) * (x / 0.5f);
    return 0.27f + (0.55f - 0.27f) * ((x - 0.5f) / 0.5f);
}

std::string lower(std::string_view s) {
    std::string out(s);
    for (char& c : out) c = char(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

}  // namespace

std::vector<uint8_t> WarpRamp::to_rgb8() const {
    std::vector<uint8_t> out;
    out.reserve(kWarpRampSize * 3);
    for (const glm::vec3& c : rgb) {
        for (int i = 0; i < 3; ++i) {
            out.push_back(uint8_t(std::lround(std::clamp(c[i], 0.0f, 1.0f) * 255.0f)));
        }
    }
    return out;
}

WarpRamp tf2_warp_ramp() {
    // Multipliers on the brightness: the shadow side leans blue (the paper's cool ambient-like
    // shadow), the terminator band leans red (its warm "subsurface" band), the lit side is grey.
    const glm::vec3 cool(0.80f, 0.88f, 1.35f);
    const glm::vec3 warm(1.30f, 0.90f, 0.78f);
    WarpRamp ramp;
    for (int i = 0; i < kWarpRampSize; ++i) {
        const float x = entry_x(i);
        const float coolness = 1.0f - smoothstep(0.30f, 0.50f, x);
        const float band = std::exp(-std::pow((x - 0.5f) / 0.06f, 2.0f));  // ~0.1 wide
        glm::vec3 tint = glm::mix(glm::vec3(1.0f), cool, coolness);
        tint = glm::mix(tint, warm, band);
        ramp.rgb[size_t(i)] = glm::clamp(tf2_value(x) * tint, 0.0f, 1.0f);
    }
    return ramp;
}

WarpRamp neutral_warp_ramp() {
    WarpRamp ramp;
    for (int i = 0; i < kWarpRampSize; ++i) ramp.rgb[size_t(i)] = glm::vec3(entry_x(i) * 0.5f);
    return ramp;
}

WarpRamp cel_warp_ramp() {
    // Band edges sit where half-Lambert crosses 35% and 65%: the back third, a mid band around
    // the terminator, the lit third. Values x2 give 0.36, 0.76 and 1.1.
    WarpRamp ramp;
    for (int i = 0; i < kWarpRampSize; ++i) {
        const float x = entry_x(i);
        const float v = x < 0.35f ? 0.18f : (x < 0.65f ? 0.38f : 0.55f);
        ramp.rgb[size_t(i)] = glm::vec3(v);
    }
    return ramp;
}

std::optional<WarpRamp> builtin_warp_ramp(std::string_view name) {
    const std::string n = lower(name);
    if (n == "tf2") return tf2_warp_ramp();
    if (n == "neutral") return neutral_warp_ramp();
    if (n == "cel") return cel_warp_ramp();
    return std::nullopt;
}

WarpRampResult ramp_from_image(const RampImage& image, const std::string& file) {
    WarpRampResult out;
    if (image.width < 2 || image.height < 1) {
        out.error = file + ": ramp image is " + std::to_string(image.width) + "x" +
                    std::to_string(image.height) + ", needs a width of at least 2";
        return out;
    }
    if (image.rgb.size() != size_t(image.width) * size_t(image.height) * 3) {
        out.error = file + ": ramp image pixel buffer does not match its size";
        return out;
    }
    const uint8_t* row = image.rgb.data() + size_t(image.height / 2) * size_t(image.width) * 3;
    auto texel = [&](int x) {
        const uint8_t* p = row + size_t(x) * 3;
        return glm::vec3(p[0], p[1], p[2]) / 255.0f;
    };
    WarpRamp ramp;
    // Entry i samples the image at the same relative position, first and last texel exactly
    // at the ends, so a 2-texel image gives a straight gradient between its two colours.
    const float scale = float(image.width - 1) / float(kWarpRampSize - 1);
    for (int i = 0; i < kWarpRampSize; ++i) {
        const float sx = float(i) * scale;
        const int x0 = std::min(int(sx), image.width - 2);
        const float f = sx - float(x0);
        ramp.rgb[size_t(i)] = glm::mix(texel(x0), texel(x0 + 1), f);
    }
    out.ramp = ramp;
    return out;
}

WarpRampResult find_warp_ramp(std::string_view name_or_path, const RampFileReader& read_file,
                              const uint8_t* palette) {
    if (auto builtin = builtin_warp_ramp(name_or_path)) return {builtin, {}};
    const std::string path(name_or_path);
    if (path.empty()) return {std::nullopt, "light warp ramp: empty name"};
    std::optional<std::vector<uint8_t>> bytes;
    if (read_file) bytes = read_file(path);
    if (!bytes) {
        return {std::nullopt,
                path + ": no such light warp ramp (not tf2, neutral or cel, and no such file)"};
    }
    return decode_warp_ramp(*bytes, path, palette);
}

}  // namespace nq::npr::illustrative

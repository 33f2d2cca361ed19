// Small statistics over screenshots for the engine tests: colours, brightness, regions.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <string>

#include "video/png_io.h"

namespace nq::test {

using Rgb = std::array<int, 3>;

inline Rgb pixel(const RgbImage& image, int x, int y) {
    size_t i = (static_cast<size_t>(y) * image.width + x) * 3;
    return {image.rgb[i], image.rgb[i + 1], image.rgb[i + 2]};
}

inline float luminance(const Rgb& c) {
    return 0.299f * c[0] + 0.587f * c[1] + 0.114f * c[2];
}

inline bool near_colour(const Rgb& a, const Rgb& b, int tolerance) {
    for (int i = 0; i < 3; ++i) {
        if (std::abs(a[i] - b[i]) > tolerance) return false;
    }
    return true;
}

inline bool is_black(const Rgb& c, int tolerance = 0) {
    return near_colour(c, {0, 0, 0}, tolerance);
}

// A rectangle of rows and columns: [x0, x1) x [y0, y1).
struct PixelRect {
    int x0, y0, x1, y1;
    int area() const { return std::max(0, x1 - x0) * std::max(0, y1 - y0); }
};

inline PixelRect whole(const RgbImage& image) {
    return {0, 0, image.width, image.height};
}

struct RegionStats {
    double mean_luminance = 0;
    double luminance_stddev = 0;
    std::array<double, 3> mean_rgb{};
    size_t distinct_colours = 0;
    double most_common_fraction = 0;  // share of the most frequent colour
};

inline RegionStats region_stats(const RgbImage& image, const PixelRect& r) {
    RegionStats s;
    std::map<uint32_t, size_t> counts;
    double sum = 0, sum_sq = 0;
    for (int y = r.y0; y < r.y1; ++y) {
        for (int x = r.x0; x < r.x1; ++x) {
            Rgb c = pixel(image, x, y);
            double l = luminance(c);
            sum += l;
            sum_sq += l * l;
            for (int i = 0; i < 3; ++i) s.mean_rgb[i] += c[i];
            ++counts[uint32_t(c[0]) << 16 | uint32_t(c[1]) << 8 | uint32_t(c[2])];
        }
    }
    double n = std::max(1, r.area());
    s.mean_luminance = sum / n;
    s.luminance_stddev = std::sqrt(std::max(0.0, sum_sq / n - s.mean_luminance * s.mean_luminance));
    for (double& m : s.mean_rgb) m /= n;
    s.distinct_colours = counts.size();
    size_t most = 0;
    for (const auto& [colour, count] : counts) most = std::max(most, count);
    s.most_common_fraction = most / n;
    return s;
}

// Hue in degrees (0..360) and saturation (0..1) of a colour, HSV style.
inline std::pair<float, float> hue_saturation(const Rgb& c) {
    int hi = std::max({c[0], c[1], c[2]}), lo = std::min({c[0], c[1], c[2]});
    if (hi == 0 || hi == lo) return {0.0f, 0.0f};
    float d = float(hi - lo), h;
    if (hi == c[0]) {
        h = 60.0f * std::fmod((c[1] - c[2]) / d + 6.0f, 6.0f);
    } else if (hi == c[1]) {
        h = 60.0f * ((c[2] - c[0]) / d + 2.0f);
    } else {
        h = 60.0f * ((c[0] - c[1]) / d + 4.0f);
    }
    return {h, d / hi};
}

// Pixels of clearly saturated colour whose hue lies in [from, to) degrees (wrapping past 360).
inline size_t count_hue(const RgbImage& image, float from, float to, float min_saturation = 0.4f,
                        int min_value = 40) {
    size_t n = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            Rgb c = pixel(image, x, y);
            if (std::max({c[0], c[1], c[2]}) < min_value) continue;
            auto [h, s] = hue_saturation(c);
            bool in = from <= to ? (h >= from && h < to) : (h >= from || h < to);
            if (s >= min_saturation && in) ++n;
        }
    }
    return n;
}

// The built-in showroom's four models are on screen: a red cube, a blue step, a green sphere
// and a yellow torus (each covers hundreds of pixels at 320x240).
inline void expect_showroom_colours(const RgbImage& image) {
    EXPECT_GT(count_hue(image, 345, 15), 50u) << "no red";
    EXPECT_GT(count_hue(image, 45, 70), 50u) << "no yellow";
    EXPECT_GT(count_hue(image, 90, 150), 50u) << "no green";
    EXPECT_GT(count_hue(image, 200, 250), 50u) << "no blue";
}

// Loads a screenshot, failing the calling test (ASSERT_NO_FATAL_FAILURE) when it cannot.
inline void load_screenshot(const std::string& path, RgbImage& out) {
    auto image = read_png(path);
    ASSERT_TRUE(image) << path << ": " << image.error().to_string();
    out = std::move(image.value());
}

}  // namespace nq::test

// Reading the technical style's screenshots: the object-id reference (tech_shading 3 paints
// every alias entity flat in a pure primary/secondary colour chosen by its number), outlines of
// those id regions, edge pixels (what one setting added over the reference), and distances
// between pixel sets. Independent of the renderer: plain pixel arithmetic on the PNGs.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "engine_image_checks.h"

namespace nq::test::technical {

// The id colours (as the plugin's object_id_color): components 0, 128 or 255, greys left out,
// the six pure colours first; entity `number` gets colour number % 24.
inline constexpr int kIdColours = 24;

inline Rgb id_colour(uint32_t number) {
    static const Rgb kColours[kIdColours] = {
        {255, 0, 0},     {0, 255, 0},     {0, 0, 255},     {255, 255, 0},   {255, 0, 255},
        {0, 255, 255},   {255, 128, 0},   {255, 0, 128},   {128, 255, 0},   {0, 255, 128},
        {128, 0, 255},   {0, 128, 255},   {128, 0, 0},     {0, 128, 0},     {0, 0, 128},
        {128, 128, 0},   {128, 0, 128},   {0, 128, 128},   {255, 255, 128}, {255, 128, 255},
        {128, 255, 255}, {255, 128, 128}, {128, 255, 128}, {128, 128, 255}};
    return kColours[number % kIdColours];
}

using Mask = std::vector<uint8_t>;  // one byte per pixel, row-major

inline Mask mask_where(const RgbImage& image, auto predicate) {
    Mask m(static_cast<size_t>(image.width) * image.height, 0);
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            m[static_cast<size_t>(y) * image.width + x] = predicate(x, y) ? 1 : 0;
        }
    }
    return m;
}

// Pixels exactly of entity `number`'s id colour.
inline Mask id_mask(const RgbImage& image, uint32_t number) {
    const Rgb c = id_colour(number);
    return mask_where(image, [&](int x, int y) { return pixel(image, x, y) == c; });
}

inline Mask mask_union(const Mask& a, const Mask& b) {
    Mask m(a.size());
    for (size_t i = 0; i < a.size(); ++i) m[i] = a[i] | b[i];
    return m;
}

// Mask pixels with a 4-neighbour outside the mask. The image border is not an outline: a model
// cut off by the screen edge has no silhouette there.
inline Mask outline(const Mask& m, int width, int height) {
    Mask out(m.size(), 0);
    auto at = [&](int x, int y) {
        if (x < 0 || y < 0 || x >= width || y >= height) return true;
        return m[size_t(y) * width + x] != 0;
    };
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            if (!at(x, y)) continue;
            if (!at(x - 1, y) || !at(x + 1, y) || !at(x, y - 1) || !at(x, y + 1)) {
                out[size_t(y) * width + x] = 1;
            }
        }
    }
    return out;
}

// Whether `m` has a pixel within `radius` (Chebyshev) of (x, y).
inline bool near_mask(const Mask& m, int width, int height, int x, int y, int radius) {
    for (int dy = -radius; dy <= radius; ++dy) {
        for (int dx = -radius; dx <= radius; ++dx) {
            int px = x + dx, py = y + dy;
            if (px >= 0 && py >= 0 && px < width && py < height && m[size_t(py) * width + px]) {
                return true;
            }
        }
    }
    return false;
}

inline size_t count(const Mask& m) {
    return static_cast<size_t>(std::count(m.begin(), m.end(), uint8_t{1}));
}

// Share of the `from` pixels that have a `to` pixel within `radius`.
inline double share_near(const Mask& from, const Mask& to, int width, int height, int radius) {
    size_t total = 0, hit = 0;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            if (!from[size_t(y) * width + x]) continue;
            ++total;
            hit += near_mask(to, width, height, x, y, radius);
        }
    }
    return total ? static_cast<double>(hit) / total : 0.0;
}

struct Box {
    int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;  // inclusive; empty when x1 < x0
    bool empty() const { return x1 < x0; }
    bool contains(int x, int y) const { return x >= x0 && x <= x1 && y >= y0 && y <= y1; }
    Box grown(int by) const { return {x0 - by, y0 - by, x1 + by, y1 + by}; }
};

inline Box bounding_box(const Mask& m, int width, int height) {
    Box b;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            if (!m[size_t(y) * width + x]) continue;
            b.x0 = std::min(b.x0, x), b.y0 = std::min(b.y0, y);
            b.x1 = std::max(b.x1, x), b.y1 = std::max(b.y1, y);
        }
    }
    return b;
}

}  // namespace nq::test::technical

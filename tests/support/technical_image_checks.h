// Reading the technical style's screenshots: the object-id reference (tech_shading 3 paints
// every alias entity flat in a pure primary/secondary colour chosen by its number), outlines of
// those id regions, edge pixels (what one setting added over the reference), and distances
// between pixel sets: engine/quality/edge_quality.h (the rules the benchmark report uses too),
// plus what only these tests need.
#pragma once

#include <algorithm>
#include <cstdint>

#include "support/engine_image_checks.h"
#include "quality/edge_quality.h"

namespace nq::test::technical {

using quality::kIdColourCount;
using quality::mask_union;
using quality::share_near;
using Mask = quality::PixelMask;

inline constexpr int kIdColours = kIdColourCount;

inline Rgb id_colour(uint32_t number) {
    const quality::Rgb8 c = quality::id_colour(number);
    return {c.r, c.g, c.b};
}

inline Mask mask_where(const RgbImage& image, auto predicate) {
    Mask m{image.width, image.height,
           std::vector<uint8_t>(static_cast<size_t>(image.width) * image.height, 0)};
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            m.bits[static_cast<size_t>(y) * image.width + x] = predicate(x, y) ? 1 : 0;
        }
    }
    return m;
}

// Pixels exactly of entity `number`'s id colour.
inline Mask id_mask(const RgbImage& image, uint32_t number) {
    return quality::id_pixels(image, number);
}

inline Mask outline(const Mask& m) {
    return quality::region_outline(m);
}

inline size_t count(const Mask& m) {
    return m.count();
}

struct Box {
    int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;  // inclusive; empty when x1 < x0
    bool empty() const { return x1 < x0; }
    bool contains(int x, int y) const { return x >= x0 && x <= x1 && y >= y0 && y <= y1; }
    Box grown(int by) const { return {x0 - by, y0 - by, x1 + by, y1 + by}; }
};

inline Box bounding_box(const Mask& m) {
    Box b;
    for (int y = 0; y < m.height; ++y) {
        for (int x = 0; x < m.width; ++x) {
            if (!m.at(x, y)) continue;
            b.x0 = std::min(b.x0, x), b.y0 = std::min(b.y0, y);
            b.x1 = std::max(b.x1, x), b.y1 = std::max(b.y1, y);
        }
    }
    return b;
}

}  // namespace nq::test::technical

#include "quality/edge_quality.h"

#include <algorithm>

namespace nq::quality {
namespace {

Rgb8 pixel(const RgbImage& image, int x, int y) {
    const size_t at = (static_cast<size_t>(y) * image.width + x) * 3;
    return {image.rgb[at], image.rgb[at + 1], image.rgb[at + 2]};
}

template <class Predicate>
PixelMask mask_where(int width, int height, Predicate predicate) {
    PixelMask m{width, height, std::vector<uint8_t>(static_cast<size_t>(width) * height, 0)};
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x)
            m.bits[static_cast<size_t>(y) * width + x] = predicate(x, y);
    }
    return m;
}

// Which id colour a pixel has: its index, or -1.
int id_index(const Rgb8& c) {
    for (int i = 0; i < kIdColourCount; ++i) {
        if (c == id_colour(static_cast<uint32_t>(i))) return i;
    }
    return -1;
}

bool is_black(const Rgb8& c) {
    return c.r == 0 && c.g == 0 && c.b == 0;
}

bool near(const PixelMask& m, int x, int y, int radius) {
    for (int dy = -radius; dy <= radius; ++dy) {
        for (int dx = -radius; dx <= radius; ++dx) {
            if (m.at(x + dx, y + dy)) return true;
        }
    }
    return false;
}

}  // namespace

Rgb8 id_colour(uint32_t number) {
    static const Rgb8 kColours[kIdColourCount] = {
        {255, 0, 0},     {0, 255, 0},     {0, 0, 255},     {255, 255, 0},   {255, 0, 255},
        {0, 255, 255},   {255, 128, 0},   {255, 0, 128},   {128, 255, 0},   {0, 255, 128},
        {128, 0, 255},   {0, 128, 255},   {128, 0, 0},     {0, 128, 0},     {0, 0, 128},
        {128, 128, 0},   {128, 0, 128},   {0, 128, 128},   {255, 255, 128}, {255, 128, 255},
        {128, 255, 255}, {255, 128, 128}, {128, 255, 128}, {128, 128, 255}};
    return kColours[number % kIdColourCount];
}

bool PixelMask::at(int x, int y) const {
    return x >= 0 && y >= 0 && x < width && y < height &&
           bits[static_cast<size_t>(y) * width + x] != 0;
}

size_t PixelMask::count() const {
    return static_cast<size_t>(std::count(bits.begin(), bits.end(), uint8_t{1}));
}

PixelMask id_pixels(const RgbImage& reference, uint32_t number) {
    const Rgb8 c = id_colour(number);
    return mask_where(reference.width, reference.height,
                      [&](int x, int y) { return pixel(reference, x, y) == c; });
}

PixelMask any_id_pixels(const RgbImage& reference) {
    return mask_where(reference.width, reference.height,
                      [&](int x, int y) { return id_index(pixel(reference, x, y)) >= 0; });
}

PixelMask region_outline(const PixelMask& region) {
    auto inside = [&](int x, int y) {
        const bool off = x < 0 || y < 0 || x >= region.width || y >= region.height;
        return off || region.at(x, y);
    };
    return mask_where(region.width, region.height, [&](int x, int y) {
        return region.at(x, y) &&
               (!inside(x - 1, y) || !inside(x + 1, y) || !inside(x, y - 1) || !inside(x, y + 1));
    });
}

PixelMask mask_union(const PixelMask& a, const PixelMask& b) {
    PixelMask m = a;
    for (size_t i = 0; i < m.bits.size() && i < b.bits.size(); ++i) m.bits[i] |= b.bits[i];
    return m;
}

PixelMask id_outlines(const RgbImage& reference) {
    PixelMask all = mask_where(reference.width, reference.height, [](int, int) { return false; });
    for (int i = 0; i < kIdColourCount; ++i) {
        PixelMask region = id_pixels(reference, static_cast<uint32_t>(i));
        if (region.count() > 0) all = mask_union(all, region_outline(region));
    }
    return all;
}

PixelMask line_pixels(const RgbImage& drawn, const RgbImage& reference) {
    if (drawn.width != reference.width || drawn.height != reference.height) return {};
    return mask_where(drawn.width, drawn.height, [&](int x, int y) {
        return is_black(pixel(drawn, x, y)) && !is_black(pixel(reference, x, y));
    });
}

double share_near(const PixelMask& from, const PixelMask& to, int radius) {
    size_t total = 0, hit = 0;
    for (int y = 0; y < from.height; ++y) {
        for (int x = 0; x < from.width; ++x) {
            if (!from.at(x, y)) continue;
            ++total;
            hit += near(to, x, y, radius);
        }
    }
    return total ? static_cast<double>(hit) / static_cast<double>(total) : 0.0;
}

SilhouetteScore score_silhouettes(const RgbImage& reference, const RgbImage& drawn) {
    const PixelMask outlines = id_outlines(reference);
    const PixelMask lines = line_pixels(drawn, reference);
    SilhouetteScore score;
    score.outline_pixels = outlines.count();
    score.line_pixels = lines.count();
    score.recall = share_near(outlines, lines, 1);
    score.precision = share_near(lines, outlines, 2);
    score.on_models = share_near(lines, any_id_pixels(reference), 2);
    return score;
}

double change_rate(std::span<const PixelMask> frames, int radius) {
    if (frames.size() < 2) return 0.0;
    // Pixels of `from` with no `to` pixel within the radius.
    auto unmatched = [radius](const PixelMask& from, const PixelMask& to) {
        size_t n = 0;
        for (int y = 0; y < from.height; ++y) {
            for (int x = 0; x < from.width; ++x) n += from.at(x, y) && !near(to, x, y, radius);
        }
        return n;
    };
    double sum = 0;
    for (size_t i = 1; i < frames.size(); ++i) {
        const PixelMask& a = frames[i - 1];
        const PixelMask& b = frames[i];
        const size_t present = a.count() + b.count();
        if (present) sum += double(unmatched(a, b) + unmatched(b, a)) / double(present);
    }
    return sum / static_cast<double>(frames.size() - 1);
}

FlickerScore score_flicker(std::span<const RgbImage> references, std::span<const RgbImage> drawn) {
    FlickerScore score;
    const size_t n = std::min(references.size(), drawn.size());
    std::vector<PixelMask> lines, outlines;
    for (size_t i = 0; i < n; ++i) {
        lines.push_back(line_pixels(drawn[i], references[i]));
        outlines.push_back(id_outlines(references[i]));
    }
    score.frames = n;
    score.lines = change_rate(lines);
    score.outlines = change_rate(outlines);
    score.excess = score.lines - score.outlines;
    return score;
}

}  // namespace nq::quality

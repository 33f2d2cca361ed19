// Image quality of a style's lines, measured on screenshots: how well the lines a frame draws
// follow the object silhouettes of an object-id reference of the same frame, and how much they
// flicker from frame to frame beyond what the objects' own outlines do. Used by the tests and
// by the benchmark report (edgequality, demos/benchmark.sh), so both judge with one rule.
//
// The reference is the technical style's `tech_shading 3` picture: every alias entity flat in
// one of kIdColourCount id colours, everything else in other colours. Its outlines are the
// id regions' boundary pixels (a 4-neighbour of another colour; the image border is not an
// outline). The lines of a frame are its pure black pixels that are not black in the reference.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "video/png_io.h"

namespace nq::quality {

inline constexpr int kIdColourCount = 24;

struct Rgb8 {
    uint8_t r = 0, g = 0, b = 0;
    bool operator==(const Rgb8&) const = default;
};

// The id colour of entity `number` (components 0, 128 or 255, no greys; the six pure colours
// first), as the technical plugin paints it. Written out here, not taken from the plugin: a
// measure of the renderer must not take the renderer's word.
Rgb8 id_colour(uint32_t number);

// One byte per pixel, row-major.
struct PixelMask {
    int width = 0;
    int height = 0;
    std::vector<uint8_t> bits;

    bool at(int x, int y) const;
    size_t count() const;
};

// Pixels of exactly entity `number`'s id colour / of any id colour.
PixelMask id_pixels(const RgbImage& reference, uint32_t number);
PixelMask any_id_pixels(const RgbImage& reference);
// The pixels of `region` with a 4-neighbour outside it (off the image counts as inside).
PixelMask region_outline(const PixelMask& region);
// The boundary pixels of every id colour's region (the union of their region outlines).
PixelMask id_outlines(const RgbImage& reference);
PixelMask mask_union(const PixelMask& a, const PixelMask& b);
// Pure black pixels of `drawn` that are not black in `reference` (same size).
PixelMask line_pixels(const RgbImage& drawn, const RgbImage& reference);
// Share of the `from` pixels with a `to` pixel within `radius` (Chebyshev); 0 when `from` is
// empty.
double share_near(const PixelMask& from, const PixelMask& to, int radius);

struct SilhouetteScore {
    double recall = 0;     // outline pixels with a line pixel within 1 px
    double precision = 0;  // line pixels within 2 px of an outline
    double on_models = 0;  // line pixels within 2 px of an id region (inner folds count)
    size_t outline_pixels = 0;
    size_t line_pixels = 0;
};
SilhouetteScore score_silhouettes(const RgbImage& reference, const RgbImage& drawn);

// Between consecutive masks: the pixels that appeared (set in the second with none within
// `radius` in the first) and vanished (the reverse), over the pixels set in both masks,
// averaged over the pairs (0 for fewer than two masks). The radius lets a line move by a pixel
// or be drawn wider than an outline without counting as a change.
double change_rate(std::span<const PixelMask> frames, int radius = 1);

struct FlickerScore {
    double lines = 0;     // change_rate of the frames' lines
    double outlines = 0;  // change_rate of the references' outlines (the objects' own motion)
    double excess = 0;    // lines - outlines: what the lines change beyond the objects
    size_t frames = 0;
};
// `references[i]` and `drawn[i]` are frame i; both lists the same length and image size.
FlickerScore score_flicker(std::span<const RgbImage> references, std::span<const RgbImage> drawn);

}  // namespace nq::quality

// The Kuwahara filter on tiling RGB8 textures: each pixel takes the mean colour of whichever of
// the four (radius + 1) x (radius + 1) quadrants meeting at it has the lowest colour variance,
// so noise inside regions is flattened while an edge stays sharp (the quadrants on the edge's
// own side are the calm ones). Quake textures tile, so the neighbourhood wraps around the
// image's borders (like GL_REPEAT) and a tiling texture stays tileable.
//
// Speed: means and variances come from summed-area tables of R, G, B and R^2 + G^2 + B^2, so a
// box costs 4 table reads whatever the radius, and each (radius + 1)^2 box is evaluated once and
// shared by the four pixels whose quadrant it is. The tables hold uint32 and box sums are taken
// modulo 2^32: each box sum itself is small enough (< 2^32) to come out exact even though the
// running totals wrap.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace nq::npr::illustrative {

// The largest radius accepted; bigger ones are clamped (a texture is >= 16 px and a radius
// over ~8 paints it flat anyway).
inline constexpr int kMaxKuwaharaRadius = 16;

// `rgb`: width * height * 3 bytes. `out` is resized to match. radius <= 0 copies the image.
// Nothing happens (out cleared) when the sizes do not match.
void kuwahara_filter(std::span<const uint8_t> rgb, int width, int height, int radius,
                     std::vector<uint8_t>& out);

}  // namespace nq::npr::illustrative

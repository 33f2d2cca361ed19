// Pictures as the GPU takes them: 8-bit RGBA, straight alpha, top row first. Quake's pictures
// are palette indices; `indexed_to_rgba` colours them with the game palette.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "formats/lmp.h"
#include "formats/palette.h"

namespace nq {

struct RgbaImage {
    int width = 0;
    int height = 0;
    std::vector<uint8_t> rgba;  // width * height * 4 bytes

    bool empty() const { return width <= 0 || height <= 0 || rgba.empty(); }
};

// width x height palette indices (row-major; fewer than that count as transparent) through the
// palette; `transparent_index` becomes alpha 0, every other index alpha 255.
RgbaImage indexed_to_rgba(int width, int height, std::span<const uint8_t> indices,
                          const Palette& palette, uint8_t transparent_index);

// A qpic (status-bar pictures, gfx/*.lmp) through the palette; index 255 is transparent.
RgbaImage pic_to_rgba(const Pic& pic, const Palette& palette);

}  // namespace nq

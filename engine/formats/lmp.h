// 8-bit palettised pictures: the "qpic" layout of gfx/*.lmp files and of WAD2 'B' lumps
// (int32 width, int32 height, width*height palette indices, row-major), and the console font
// CONCHARS, which is stored raw (128x128 indices, no header).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "common/result.h"
#include "formats/wad.h"

namespace nq {

inline constexpr int kConcharsSize = 128;  // 16x16 glyphs of 8x8 pixels

struct Pic {
    int32_t width = 0;
    int32_t height = 0;
    std::vector<uint8_t> pixels;  // width * height palette indices (255 = transparent)
    std::vector<std::string> warnings;

    uint8_t at(int x, int y) const { return pixels[static_cast<size_t>(y) * width + x]; }
};

// `base_offset` is where `data` starts inside `name` (a WAD lump), so errors point at the
// right byte of the file.
Result<Pic> parse_qpic(std::span<const uint8_t> data, const std::string& name,
                       uint64_t base_offset = 0);
Result<Pic> parse_conchars(std::span<const uint8_t> data, const std::string& name,
                           uint64_t base_offset = 0);

// Decodes a WAD2 lump as a picture: CONCHARS (by type 'E' or by name, since id's gfx.wad
// files it as type 'D') as the raw font, type 'B' as a qpic. Other types and compressed lumps
// are errors naming the lump.
Result<Pic> parse_wad_pic(const Wad& wad, const WadLump& lump);

}  // namespace nq

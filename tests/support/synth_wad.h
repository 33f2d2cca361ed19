// Writers for synthetic WAD2 archives and the loose .lmp files (qpic, palette, colormap):
// test fixtures and fuzz seeds. Directory fields can be overridden to build malformed cases.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "support/seed_file.h"

namespace nq::test {

struct SynthWad {
    struct Lump {
        std::string name;
        uint8_t type = 0x42;  // qpic
        uint8_t compression = 0;
        std::vector<uint8_t> data;
        // Directory fields; unset means "where/what the writer actually put".
        std::optional<int32_t> file_offset, disk_size, size;
    };
    std::string ident = "WAD2";
    std::optional<int32_t> num_lumps;   // unset: lumps.size()
    std::optional<int32_t> dir_offset;  // unset: right after the lump data
    std::vector<Lump> lumps;
};

// Layout: 12-byte header, lump data in order, then the 32-byte directory entries.
std::vector<uint8_t> write_wad(const SynthWad& wad);
// Offset at which write_wad puts lump `index`'s data (ignoring overrides).
size_t synth_wad_lump_offset(const SynthWad& wad, size_t index);

std::vector<uint8_t> write_qpic(int32_t width, int32_t height, const std::vector<uint8_t>& pixels);
std::vector<uint8_t> gradient_pixels(size_t count, uint8_t first);
// 768 bytes: colour i = (i, 255 - i, i / 2).
std::vector<uint8_t> synthetic_palette_lmp();
// 64 x 256 bytes: level l maps index i to i for fullbrights, else to (i * (63 - l)) / 63;
// `id_trailing_byte` appends the extra byte id's colormap.lmp carries.
std::vector<uint8_t> synthetic_colormap_lmp(bool id_trailing_byte);

// "NUM_0" 24x24 qpic, "CONCHARS" raw 128x128 filed as type 'D' (as in id's gfx.wad),
// "Palette" type '@', "face1" 3x2 qpic. Valid.
SynthWad sample_wad();

// WADs (valid and malformed) plus .lmp pictures, palettes and colormaps for fuzzing.
std::vector<SeedFile> synthetic_wad_seeds();

}  // namespace nq::test

// WAD2 archives (gfx.wad): a 12-byte header ("WAD2", lump count, directory offset) and a
// directory of 32-byte entries: file offset, size on disk, size, type, compression, 2 pad
// bytes, 16-byte NUL-padded name. Names are looked up case-insensitively, as the engine does.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "common/result.h"

namespace nq {

// Lump types found in Quake WAD2 files (the type byte is an ASCII letter).
enum class WadLumpType : uint8_t {
    Palette = 0x40,   // '@': 768-byte palette
    QPic = 0x42,      // 'B': status-bar / menu picture (width, height, pixels)
    MipTex = 0x44,    // 'D': mip texture (id's gfx.wad also files CONCHARS under this type)
    ConChars = 0x45,  // 'E': raw 128x128 console font
};

const char* wad_lump_type_name(uint8_t type);  // "palette", "qpic", ... or "unknown"

struct WadLump {
    std::string name;  // as stored, case preserved
    uint8_t type = 0;
    uint8_t compression = 0;  // 0 = stored; anything else is unsupported
    uint32_t file_offset = 0;
    uint32_t disk_size = 0;
    uint32_t size = 0;

    bool is_compressed() const { return compression != 0; }
};

struct Wad {
    std::string file_name;
    // One copy of the whole file: lumps are ranges in it, so a directory whose entries all
    // point at the same bytes costs no extra memory.
    std::vector<uint8_t> bytes;
    std::vector<WadLump> lumps;  // in directory order
    std::vector<std::string> warnings;

    // First lump whose name matches case-insensitively, or nullptr.
    const WadLump* find(std::string_view name) const;
    // The lump's stored bytes (a view into `bytes`, valid while this Wad lives), or an error
    // naming the lump and its offset when the lump is compressed, which no Quake engine
    // supports.
    Result<std::span<const uint8_t>> lump_bytes(const WadLump& lump) const;
};

// Every directory entry must lie inside the file (errors otherwise); odd but harmless content
// (unknown types, duplicate names, size mismatches) becomes a warning.
Result<Wad> parse_wad(std::span<const uint8_t> data, const std::string& name);

// ASCII case-insensitive name comparison, the way Quake matches lump names.
bool names_equal_ignoring_case(std::string_view a, std::string_view b);

}  // namespace nq

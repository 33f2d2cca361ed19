#include "formats/wad.h"

#include <cctype>
#include <cstdio>
#include <unordered_set>

#include "common/byte_reader.h"

namespace nq {

namespace {

constexpr size_t kHeaderBytes = 12;
constexpr size_t kEntryBytes = 32;
constexpr size_t kNameBytes = 16;

std::string lower_case(std::string_view s) {
    std::string out(s);
    for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

std::string hex_byte(uint8_t v) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "0x%02x", v);
    return buf;
}

bool is_known_lump_type(uint8_t type) {
    switch (static_cast<WadLumpType>(type)) {
        case WadLumpType::Palette:
        case WadLumpType::QPic:
        case WadLumpType::MipTex:
        case WadLumpType::ConChars:
            return true;
        default:
            return false;
    }
}

// Reads a non-negative int32 field, failing at its own offset with `what` in the message.
uint32_t read_size_field(ByteReader& in, const std::string& what) {
    size_t at = in.tell();
    int32_t v = in.i32();
    if (v < 0) in.fail_at(at, what + " is negative (" + std::to_string(v) + ")");
    return static_cast<uint32_t>(v);
}

WadLump read_entry(ByteReader& dir, size_t index) {
    const std::string label = "lump " + std::to_string(index);
    WadLump lump;
    lump.file_offset = read_size_field(dir, label + " file offset");
    lump.disk_size = read_size_field(dir, label + " disk size");
    lump.size = read_size_field(dir, label + " size");
    lump.type = dir.u8();
    lump.compression = dir.u8();
    dir.skip(2);  // padding
    lump.name = dir.fixed_string(kNameBytes);
    return lump;
}

void check_entry_range(const ByteReader& in, const WadLump& lump, size_t entry_pos, size_t index) {
    uint64_t end = uint64_t{lump.file_offset} + lump.disk_size;
    if (end > in.size()) {
        in.fail_at(entry_pos,
                   "lump " + std::to_string(index) + " '" + lump.name + "' [" +
                       std::to_string(lump.file_offset) + ", +" + std::to_string(lump.disk_size) +
                       ") lies outside the file (size " + std::to_string(in.size()) + ")");
    }
}

void warn_about_entry(const WadLump& lump, size_t index, std::unordered_set<std::string>& seen,
                      std::vector<std::string>& warnings) {
    const std::string label = "lump " + std::to_string(index) + " '" + lump.name + "'";
    if (lump.name.empty()) warnings.push_back(label + " has an empty name");
    if (!seen.insert(lower_case(lump.name)).second) {
        warnings.push_back(label + " repeats an earlier name; lookups find the first");
    }
    if (!is_known_lump_type(lump.type)) {
        warnings.push_back(label + " has unknown type " + hex_byte(lump.type));
    }
    if (lump.is_compressed()) {
        warnings.push_back(label + " is compressed (" + hex_byte(lump.compression) +
                           "), which is unsupported; reading it will fail");
    } else if (lump.size != lump.disk_size) {
        warnings.push_back(label + " size " + std::to_string(lump.size) +
                           " differs from its disk size " + std::to_string(lump.disk_size) +
                           "; using the disk size");
    }
}

Wad parse_wad_body(std::span<const uint8_t> data, const std::string& name) {
    ByteReader in(data, name);
    if (in.size() < kHeaderBytes) in.fail("file too small for a WAD2 header (12 bytes)");
    std::string ident(reinterpret_cast<const char*>(in.bytes(4).data()), 4);
    if (ident != "WAD2") in.fail_at(0, "not a WAD2 file (identifier is not \"WAD2\")");
    in.seek(4);
    const int32_t num_lumps = in.i32();
    if (num_lumps < 0) in.fail_at(4, "negative lump count " + std::to_string(num_lumps));
    const size_t dir_offset = read_size_field(in, "directory offset");
    if (dir_offset > in.size()) {
        in.fail_at(8, "directory offset " + std::to_string(dir_offset) +
                          " lies past the end of the file (size " + std::to_string(in.size()) +
                          ")");
    }
    in.seek(dir_offset);
    in.require_records(num_lumps, kEntryBytes, "WAD directory");

    Wad wad;
    wad.file_name = name;
    wad.lumps.reserve(static_cast<size_t>(num_lumps));
    std::unordered_set<std::string> seen;
    for (size_t i = 0; i < static_cast<size_t>(num_lumps); ++i) {
        size_t entry_pos = in.tell();
        WadLump lump = read_entry(in, i);
        check_entry_range(in, lump, entry_pos, i);
        warn_about_entry(lump, i, seen, wad.warnings);
        wad.lumps.push_back(std::move(lump));
    }
    wad.bytes.assign(data.begin(), data.end());
    return wad;
}

}  // namespace

const char* wad_lump_type_name(uint8_t type) {
    switch (type) {
        case static_cast<uint8_t>(WadLumpType::Palette):
            return "palette";
        case static_cast<uint8_t>(WadLumpType::QPic):
            return "qpic";
        case static_cast<uint8_t>(WadLumpType::MipTex):
            return "miptex";
        case static_cast<uint8_t>(WadLumpType::ConChars):
            return "conchars";
        default:
            return "unknown";
    }
}

bool names_equal_ignoring_case(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i) {
        if (std::tolower(static_cast<unsigned char>(a[i])) !=
            std::tolower(static_cast<unsigned char>(b[i]))) {
            return false;
        }
    }
    return true;
}

const WadLump* Wad::find(std::string_view name) const {
    for (const WadLump& lump : lumps) {
        if (names_equal_ignoring_case(lump.name, name)) return &lump;
    }
    return nullptr;
}

Result<std::span<const uint8_t>> Wad::lump_bytes(const WadLump& lump) const {
    if (lump.is_compressed()) {
        return Error{file_name, lump.file_offset,
                     "lump '" + lump.name + "' is compressed (" + hex_byte(lump.compression) +
                         "); compressed WAD lumps are not supported"};
    }
    // parse_wad checked the range; re-check so a hand-edited Wad cannot read out of bounds.
    if (uint64_t{lump.file_offset} + lump.disk_size > bytes.size()) {
        return Error{file_name, lump.file_offset, "lump '" + lump.name + "' lies outside the file"};
    }
    return std::span<const uint8_t>(bytes).subspan(lump.file_offset, lump.disk_size);
}

Result<Wad> parse_wad(std::span<const uint8_t> data, const std::string& name) {
    return capture_errors(name, [&] { return parse_wad_body(data, name); });
}

}  // namespace nq

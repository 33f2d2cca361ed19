// Quake PAK archives: parsing the directory and writing a new pak.
//
// Layout (little-endian): "PACK", int32 directory offset, int32 directory length; the directory
// is an array of 64-byte entries: a 56-byte NUL-padded name, int32 file offset, int32 length.
// The parser only reads the header and the directory; entry data stays where it is, so a pak on
// disk can be indexed without loading it (see fs/pak_archive.h) and a pak in memory can hand
// out spans (pak_entry_bytes).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "common/result.h"

namespace nq {

inline constexpr size_t kPakHeaderSize = 12;
inline constexpr size_t kPakEntrySize = 64;
inline constexpr size_t kPakNameField = 56;
inline constexpr size_t kPakMaxNameLength = kPakNameField - 1;  // room for the NUL
// Far above any real pak (Quake itself stopped at 2048); keeps a lying header from making us
// read or index a 2 GiB "directory".
inline constexpr uint32_t kPakMaxEntries = 1u << 18;

struct PakHeader {
    uint32_t dir_offset = 0;
    uint32_t dir_length = 0;  // bytes; a multiple of kPakEntrySize
    uint32_t entry_count() const { return dir_length / static_cast<uint32_t>(kPakEntrySize); }
};

struct PakEntry {
    std::string name;  // '/'-separated (backslashes are normalised), case as stored
    uint32_t offset = 0;
    uint32_t size = 0;
};

struct PakDirectory {
    PakHeader header;
    // In directory order. Names are unique ignoring case: a later duplicate replaces the
    // earlier entry in its slot (with a warning). Entries with unsafe names are left out.
    std::vector<PakEntry> entries;
    size_t unsafe_entries = 0;  // entries left out because of an absolute or ".." name
    std::vector<std::string> warnings;
};

// A file to put into a pak.
struct PakFile {
    std::string name;  // '/'-separated relative path, at most kPakMaxNameLength bytes
    std::vector<uint8_t> data;
};

// Parses a whole pak held in memory.
Result<PakDirectory> parse_pak(std::span<const uint8_t> data, const std::string& name);

// The two halves of parse_pak, for a pak that stays on disk. `start` holds at least the first
// kPakHeaderSize bytes of the file (more is ignored); `file_size` is the size of the whole file.
Result<PakHeader> parse_pak_header(std::span<const uint8_t> start, uint64_t file_size,
                                   const std::string& name);
// `dir_bytes` holds exactly the header.dir_length bytes found at header.dir_offset.
Result<PakDirectory> parse_pak_directory(std::span<const uint8_t> dir_bytes,
                                         const PakHeader& header, uint64_t file_size,
                                         const std::string& name);

// The data of an entry of a pak parsed from `pak` (ranges were validated by the parser).
std::span<const uint8_t> pak_entry_bytes(std::span<const uint8_t> pak, const PakEntry& entry);

// Why `name` is unsafe as a relative path ("" if it is safe): empty, absolute, a drive letter,
// an empty, "." or ".." component, or a backslash. Used by the parser, the writer and extraction
// so that no entry name can ever address a file outside the directory it is extracted to.
std::string pak_name_problem(std::string_view name);

// Builds a pak: header, the data in the given order, then the directory. Fails (naming the
// entry) on an unsafe or over-long name, a duplicate name (ignoring case), or a total size that
// does not fit the format's int32 offsets.
Result<std::vector<uint8_t>> write_pak(std::span<const PakFile> files, const std::string& name);

}  // namespace nq

// Synthetic PAK files for tests and fuzz seeds, made by a writer independent of the engine's
// (formats/pak.cpp), so that a bug shared by both cannot hide. The raw writer writes every
// header and directory field exactly as given, which is how tests build malformed paks.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "support/engine_run.h"
#include "support/seed_file.h"

namespace nq::test {

// One directory record written verbatim. `name` is copied into the 56-byte field and padded
// with NULs; a name of 56 bytes or more fills the field with no terminator (first 56 bytes).
struct RawPakEntry {
    std::string name;
    int32_t offset = 0;
    int32_t length = 0;
};

struct RawPak {
    std::string magic = "PACK";         // first 4 bytes are written (NUL-padded if shorter)
    std::vector<uint8_t> payload;       // written right after the 12-byte header
    std::vector<RawPakEntry> entries;   // written right after the payload
    std::optional<int32_t> dir_offset;  // default: where the entries are written
    std::optional<int32_t> dir_length;  // default: 64 * entries.size()
};

std::vector<uint8_t> build_raw_pak(const RawPak& pak);

// (name, content) pairs.
using NamedText = std::pair<std::string, std::string>;

// A well-formed pak holding `files` in the given order (duplicates allowed: written as given).
std::vector<uint8_t> build_pak(const std::vector<NamedText>& files);

// Fuzz seeds: empty pak, nested names, duplicates, backslashes, shared and empty data, unsafe
// names, junk after the name's NUL.
std::vector<SeedFile> synthetic_pak_seeds();

// A scratch directory for building basedir/game trees, unique per process and instance (tests
// may run in parallel) and removed with everything in it on destruction. Throws
// std::runtime_error on any failure.
class TempGameTree {
  public:
    TempGameTree();

    const std::string& root() const { return dir_.path(); }
    // root()/relative
    std::string path(std::string_view relative) const;
    // Writes root()/relative, creating parent directories.
    void write(std::string_view relative, std::string_view content) const;
    void write_bytes(std::string_view relative, std::span<const uint8_t> bytes) const;
    void write_pak(std::string_view relative, const std::vector<NamedText>& files) const;
    void make_dir(std::string_view relative) const;

  private:
    TempDir dir_;
};

}  // namespace nq::test

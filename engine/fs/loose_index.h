// The loose (non-pak) files of one game directory, indexed by lowercase path so that lookups
// are case-insensitive on a case-sensitive host filesystem without touching the disk.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "common/result.h"

namespace nq {

struct LooseFile {
    std::string key;       // normalize_vfs_path of `relative`
    std::string relative;  // path relative to the game dir, '/'-separated, case as on disk
    uint64_t size = 0;     // at scan time
};

struct LooseScan {
    std::vector<LooseFile> files;  // sorted by key, keys unique
    std::vector<std::string> warnings;
};

// Walks `dir` recursively. Hidden entries (".git", ".DS_Store") are skipped: they are never
// game data and can be large. Symbolic links are followed, wherever they lead (a `progs/` linked
// to data kept elsewhere is the usual case), each directory entered once: a link back to a
// directory already walked (a loop, or a second link to the same place) is not entered again,
// with a warning. Two files whose names differ only in case keep the one whose on-disk name
// sorts first, with a warning.
Result<LooseScan> scan_loose_files(const std::string& dir);

// The numbered paks ("pak0.pak", "PAK12.PAK", ...) at the top of a scanned game dir, in numeric
// order: the order in which they override each other.
std::vector<const LooseFile*> numbered_paks(const LooseScan& scan);

}  // namespace nq

// Moving files between a pak and a directory tree on the host: what `pak create` and
// `pak extract` do, kept here so that the rules (sorted names, no escaping the target dir) are
// testable and reusable.
#pragma once

#include <string>
#include <vector>

#include "common/result.h"
#include "formats/pak.h"
#include "fs/pak_archive.h"

namespace nq {

// Every regular file under `dir` (recursively) as a PakFile named by its '/'-separated path
// relative to `dir`, sorted by name (byte order), so the same tree always gives the same pak.
// `exclude` (e.g. the pak being written, if it lies inside `dir`) is left out. Fails, naming the
// file, on a name longer than kPakMaxNameLength or unusable in a pak, or on a read error.
Result<std::vector<PakFile>> collect_pak_files(const std::string& dir,
                                               const std::string& exclude = {});

// Writes `entry` of `pak` to `out_dir`/<entry name>, creating subdirectories. Refuses (returns
// a message; "" on success) a name that is not a safe relative path, and a target that would
// resolve outside `out_dir` through a symlink already in the tree.
std::string extract_pak_entry(const PakArchive& pak, const PakEntry& entry,
                              const std::string& out_dir);

}  // namespace nq

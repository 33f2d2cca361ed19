// Virtual paths: how the engine names game files, independent of case and host separators.
#pragma once

#include <string>
#include <string_view>

namespace nq {

// The lookup key of a game path: ASCII-lowercased, '\' turned into '/', empty and "."
// components dropped ("./Maps//START.BSP" -> "maps/start.bsp"). ".." is kept as is, so it can
// never match a file: the index only holds names found inside game dirs and paks.
std::string normalize_vfs_path(std::string_view path);

// ".BSP", "bsp" and "*.bsp" all become ".bsp"; "" stays "" (any extension).
std::string normalize_extension(std::string_view extension);

// Whether the normalized key `key` lies under the normalized directory `dir` ("" = anywhere,
// "maps" matches "maps/e1m1.bsp" but not "mapsx/a.bsp") and ends with normalized `extension`.
bool vfs_key_matches(std::string_view key, std::string_view dir, std::string_view extension);

}  // namespace nq

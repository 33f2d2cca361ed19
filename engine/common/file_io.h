// Reading and writing whole files on the host filesystem, with errors returned.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "common/result.h"

namespace nq {

// Files larger than this are refused rather than read (no Quake asset comes close).
inline constexpr uint64_t kMaxFileBytes = 1ull << 30;

Result<std::vector<uint8_t>> read_file(const std::string& path);
// Returns an empty string on success, otherwise a message naming the path and the reason.
std::string write_file(const std::string& path, std::span<const uint8_t> bytes);
// Appends `text` to the file (created if missing); "" on success, else a message as above.
std::string append_file(const std::string& path, std::string_view text);

}  // namespace nq

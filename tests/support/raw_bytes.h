// Test inputs byte for byte: whole files, and little-endian fields read or patched in place
// (the independent view of a file that parsers are checked against).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace nq::test {

// The whole file; throws std::runtime_error naming the path when it cannot be opened.
std::vector<uint8_t> raw_file(const std::string& path);
// The whole file as text; "" when it cannot be opened (a tool's missing output reads empty).
std::string text_file(const std::string& path);

// Little-endian 32-bit field at byte `at`; throws std::out_of_range past the end.
int32_t read_le32(std::span<const uint8_t> bytes, size_t at);
// Little-endian IEEE float at byte `at`; throws std::out_of_range past the end.
float read_lef32(std::span<const uint8_t> bytes, size_t at);
void poke_le32(std::vector<uint8_t>& bytes, size_t at, int32_t value);

}  // namespace nq::test

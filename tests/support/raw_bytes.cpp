#include "support/raw_bytes.h"

#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>

namespace nq::test {

std::vector<uint8_t> raw_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot open " + path);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string text_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

int32_t read_le32(std::span<const uint8_t> bytes, size_t at) {
    if (at + 4 > bytes.size()) throw std::out_of_range("read_le32 past end");
    uint32_t v = 0;
    for (int i = 0; i < 4; ++i) v |= static_cast<uint32_t>(bytes[at + i]) << (8 * i);
    return static_cast<int32_t>(v);
}

float read_lef32(std::span<const uint8_t> bytes, size_t at) {
    const auto bits = static_cast<uint32_t>(read_le32(bytes, at));
    float value;
    std::memcpy(&value, &bits, sizeof value);
    return value;
}

void poke_le32(std::vector<uint8_t>& bytes, size_t at, int32_t value) {
    if (at + 4 > bytes.size()) throw std::out_of_range("poke_le32 past end");
    auto v = static_cast<uint32_t>(value);
    for (int i = 0; i < 4; ++i) bytes[at + i] = static_cast<uint8_t>(v >> (8 * i));
}

}  // namespace nq::test

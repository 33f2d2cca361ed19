#include "formats/model_format.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstring>

namespace nq {
namespace {

bool starts_with(std::span<const uint8_t> bytes, const char (&magic)[5]) {
    return bytes.size() >= 4 && std::memcmp(bytes.data(), magic, 4) == 0;
}

bool has_suffix(const std::string& name, const char* suffix) {
    const size_t n = std::strlen(suffix);
    if (name.size() < n) return false;
    return std::equal(name.end() - std::ptrdiff_t(n), name.end(), suffix, [](char a, char b) {
        return std::tolower(static_cast<unsigned char>(a)) == b;
    });
}

}  // namespace

ModelFormat identify_model(std::span<const uint8_t> bytes) {
    if (starts_with(bytes, "IDPO")) return ModelFormat::alias;
    if (starts_with(bytes, "IDSP")) return ModelFormat::sprite;
    if (starts_with(bytes, "BSP2") || starts_with(bytes, "2PSB")) return ModelFormat::brush;
    const uint8_t bsp29[4] = {29, 0, 0, 0};  // little-endian int32 version 29
    if (bytes.size() >= 4 && std::memcmp(bytes.data(), bsp29, 4) == 0) return ModelFormat::brush;
    return ModelFormat::unknown;
}

const char* model_format_name(ModelFormat format) {
    switch (format) {
        case ModelFormat::alias:
            return "alias model (IDPO)";
        case ModelFormat::sprite:
            return "sprite (IDSP)";
        case ModelFormat::brush:
            return "brush model (BSP)";
        case ModelFormat::unknown:
            break;
    }
    return "unknown";
}

ModelFormat model_format_by_extension(const std::string& name) {
    if (has_suffix(name, ".mdl")) return ModelFormat::alias;
    if (has_suffix(name, ".spr")) return ModelFormat::sprite;
    if (has_suffix(name, ".bsp")) return ModelFormat::brush;
    return ModelFormat::unknown;
}

std::string describe_model_magic(std::span<const uint8_t> bytes) {
    if (bytes.empty()) return "an empty file";
    const size_t n = std::min<size_t>(bytes.size(), 4);
    const bool printable = std::all_of(bytes.begin(), bytes.begin() + std::ptrdiff_t(n),
                                       [](uint8_t c) { return std::isprint(c) != 0; });
    std::string text = "first bytes ";
    if (printable)
        return text + "\"" + std::string(bytes.begin(), bytes.begin() + std::ptrdiff_t(n)) + "\"";
    for (size_t i = 0; i < n; ++i) {
        char hex[4];
        std::snprintf(hex, sizeof hex, "%02x", bytes[i]);
        text += (i ? " " : "") + std::string(hex);
    }
    return text;
}

}  // namespace nq

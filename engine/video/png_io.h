// 8-bit RGB PNG files, through libpng's simplified API (which reports errors instead of
// long-jumping through C++ frames).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "common/result.h"

namespace nq {

// Rows top to bottom, 3 bytes per pixel, no padding.
struct RgbImage {
    int width = 0;
    int height = 0;
    std::vector<uint8_t> rgb;
};

// Largest side read_png accepts, so a lying header cannot ask for gigabytes.
inline constexpr int kMaxPngDimension = 16384;

// Writes `rgb` (width * height * 3 bytes, top row first). Empty string on success, otherwise
// a message naming the path.
std::string write_png(const std::string& path, int width, int height, std::span<const uint8_t> rgb);

// Reads any PNG libpng understands, converted to 8-bit RGB (alpha is composited onto black).
Result<RgbImage> read_png(const std::string& path);

}  // namespace nq

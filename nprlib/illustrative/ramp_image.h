// Decoding user light-warp ramp images from memory: PNG (libpng's simplified API, whose setjmp /
// longjmp error handling stays inside libpng, so a corrupt file only returns an error here) and
// Quake .lmp pictures (int32 width, int32 height little-endian, then width * height palette
// indices). Untrusted input: every failure names the file, the byte offset and the problem.
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "illustrative/warp_ramp.h"

namespace nq::npr::illustrative {

// A ramp image larger than this in either dimension, or in pixels, is refused: ramps are a few
// hundred texels wide, and the limit keeps a hostile header from asking for gigabytes.
inline constexpr int kMaxRampImageDimension = 4096;
inline constexpr int64_t kMaxRampImagePixels = int64_t(1) << 22;

struct RampImageResult {
    RampImage image;
    std::string error;  // empty on success
};

bool looks_like_png(std::span<const uint8_t> bytes);

RampImageResult decode_png_ramp_image(std::span<const uint8_t> bytes, const std::string& file);

// `palette`: 256 RGB triples (768 bytes).
RampImageResult decode_lmp_ramp_image(std::span<const uint8_t> bytes, const uint8_t* palette,
                                      const std::string& file);

// PNG when the bytes carry the PNG signature, otherwise .lmp (palette needed), then resampled.
WarpRampResult decode_warp_ramp(std::span<const uint8_t> bytes, const std::string& file,
                                const uint8_t* palette);

}  // namespace nq::npr::illustrative

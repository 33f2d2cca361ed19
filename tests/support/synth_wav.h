// Writers for synthetic RIFF WAVE files: test fixtures and fuzz seeds. Fields can be
// overridden so tests can build each malformed case.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "support/seed_file.h"

namespace nq::test {

struct SynthWav {
    uint16_t format = 1;  // PCM
    uint16_t channels = 1;
    uint32_t rate = 11025;
    uint16_t bits = 16;
    std::vector<int16_t> samples;         // interleaved; 8-bit files store (s >> 8) + 128
    std::optional<uint32_t> loop_start;   // writes a `cue ` chunk with one cue point
    std::optional<uint32_t> loop_length;  // writes LIST/adtl/ltxt with purpose "mark"
    std::optional<uint32_t> data_size;    // overrides the data chunk's size field
    bool write_fmt = true;
};

std::vector<uint8_t> write_wav(const SynthWav& wav);

// A few valid and malformed WAVs (8/16-bit, looped, stereo, truncated, bad sizes).
std::vector<SeedFile> synthetic_wav_seeds();

}  // namespace nq::test

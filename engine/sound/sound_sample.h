// A sound effect ready for the mixer: signed 16-bit mono at the output rate. Made once at
// precache time (Quake's ResampleSfx), so the mixer only copies and scales.
#pragma once

#include <cstdint>
#include <vector>

#include "sound/wav.h"

namespace nq {

struct SoundSample {
    std::vector<int16_t> frames;  // mono, at the output rate
    int loop_start = -1;          // in output frames; -1: plays once
    size_t length() const { return frames.size(); }
};

// Linear interpolation from the file's rate to `output_rate`; the loop start scales with it.
SoundSample resample(const WavSound& wav, int output_rate);

}  // namespace nq

// RIFF WAVE sound effects as Quake reads them: PCM, 8- or 16-bit, mono (stereo files are
// mixed down), any rate. The loop start comes from the first `cue ` point and the loop end
// from the `LIST`/`adtl`/`ltxt` chunk whose purpose is `mark` (loop start + sample length),
// as Quake's GetWavinfo reads them. Errors name the file, the byte offset and the problem.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "common/result.h"

namespace nq {

struct WavSound {
    int rate = 0;                  // samples per second
    int bits = 0;                  // 8 or 16 as stored
    int channels = 0;              // as stored; `samples` is always mono
    int loop_start = -1;           // in samples; -1: the file has no cue point
    std::vector<int16_t> samples;  // signed 16-bit mono, up to the loop end when one is set
};

Result<WavSound> parse_wav(std::span<const uint8_t> bytes, const std::string& file);

}  // namespace nq

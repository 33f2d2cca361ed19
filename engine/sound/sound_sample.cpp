#include "sound/sound_sample.h"

#include <cmath>

namespace nq {

SoundSample resample(const WavSound& wav, int output_rate) {
    SoundSample out;
    const size_t in_count = wav.samples.size();
    if (in_count == 0 || wav.rate <= 0 || output_rate <= 0) return out;
    const double step = double(wav.rate) / double(output_rate);  // input samples per output
    const size_t out_count = size_t(double(in_count) / step);
    out.frames.resize(out_count);
    for (size_t i = 0; i < out_count; ++i) {
        const double pos = double(i) * step;
        const size_t j = std::min(size_t(pos), in_count - 1);
        const size_t k = std::min(j + 1, in_count - 1);
        const double f = pos - double(j);
        const double v = double(wav.samples[j]) * (1.0 - f) + double(wav.samples[k]) * f;
        out.frames[i] = int16_t(std::lround(v));
    }
    if (wav.loop_start >= 0 && out_count > 0) {
        out.loop_start = std::min(int(double(wav.loop_start) / step), int(out_count) - 1);
    }
    return out;
}

}  // namespace nq

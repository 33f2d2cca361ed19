#include "sound/mixer.h"

#include <algorithm>
#include <cmath>

namespace nq {
namespace {

int16_t to_pcm16(float v) {
    return int16_t(std::clamp(std::lrint(v), -32768L, 32767L));
}

}  // namespace

void Mixer::mix(std::span<StereoFrame> out, const MixLevels& levels) {
    while (!out.empty()) {
        const size_t n = std::min(out.size(), kPaintFrames);
        mix_chunk(out.first(n), levels);
        out = out.subspan(n);
    }
}

void Mixer::mix_chunk(std::span<StereoFrame> out, const MixLevels& levels) {
    const size_t frames = out.size();
    std::span<float> paint(paint_.data(), 2 * frames);
    std::fill(paint.begin(), paint.end(), 0.0f);
    channels_.paint(paint, frames, levels.volume);
    if (music_ && !music_paused_ && !music_->ended()) {
        music_->paint(paint, frames, levels.bgm_volume);
    }
    for (size_t i = 0; i < frames; ++i) {
        out[i] = {to_pcm16(paint[2 * i]), to_pcm16(paint[2 * i + 1])};
    }
}

}  // namespace nq

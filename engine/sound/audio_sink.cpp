#include "sound/audio_sink.h"

#include <cmath>

namespace nq {

size_t MemorySink::frames_wanted(double frame_time, double /*mix_ahead*/) {
    clock_ += std::max(0.0, frame_time);
    const auto target = size_t(std::llround(clock_ * rate_));
    return target > frames_.size() ? target - frames_.size() : 0;
}

void MemorySink::write(std::span<const StereoFrame> frames) {
    frames_.insert(frames_.end(), frames.begin(), frames.end());
}

}  // namespace nq

#include "sound/music_stream.h"

#include <algorithm>
#include <cstring>

namespace nq {

MusicStream::MusicStream(std::unique_ptr<PcmSource> source, int output_rate, bool loop)
    : source_(std::move(source)),
      step_(double(source_->rate()) / double(std::max(output_rate, 1))),
      loop_(loop) {}

bool MusicStream::fill() {
    // Keep the frame under the read position: interpolation needs it.
    const size_t keep_from = std::min(size_t(position_), buffered_);
    std::memmove(buffer_.data(), buffer_.data() + 2 * keep_from,
                 (buffered_ - keep_from) * 2 * sizeof(int16_t));
    buffered_ -= keep_from;
    position_ -= double(keep_from);
    if (source_done_) return false;
    const size_t before = buffered_;
    bool rewound = false;  // a rewind that yields nothing again ends the track
    while (buffered_ < kChunkFrames) {
        const size_t got = source_->read(std::span(buffer_).subspan(2 * buffered_));
        buffered_ += got;
        if (got > 0) {
            rewound = false;
            continue;
        }
        // At the end of the track: loop from its start, or stop.
        if (!loop_ || rewound || !source_->rewind()) {
            source_done_ = true;
            break;
        }
        rewound = true;
    }
    return buffered_ > before;
}

size_t MusicStream::paint(std::span<float> mix, size_t frames, float gain) {
    size_t i = 0;
    for (; i < frames && !ended_; ++i) {
        size_t j = size_t(position_);
        while (j + 1 >= buffered_ && fill()) j = size_t(position_);
        if (j >= buffered_) {
            ended_ = true;
            break;
        }
        const size_t k = std::min(j + 1, buffered_ - 1);
        const float f = float(position_ - double(j));
        for (int c = 0; c < 2; ++c) {
            const float a = buffer_[2 * j + size_t(c)], b = buffer_[2 * k + size_t(c)];
            mix[2 * i + size_t(c)] += (a + (b - a) * f) * gain;
        }
        position_ += step_;
    }
    return i;
}

}  // namespace nq

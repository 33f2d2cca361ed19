// The music track being played: decoded from its PcmSource a chunk at a time into a fixed
// buffer and resampled (linear) to the output rate as the mixer asks for frames. Loops or
// stops at the end. No allocation after it is created.
#pragma once

#include <array>
#include <memory>
#include <span>
#include <string>

#include "sound/pcm_source.h"

namespace nq {

class MusicStream {
  public:
    MusicStream(std::unique_ptr<PcmSource> source, int output_rate, bool loop);

    // Adds up to `frames` stereo frames into `mix` (interleaved), scaled by gain; returns how
    // many it added (fewer only when a track that does not loop has ended).
    size_t paint(std::span<float> mix, size_t frames, float gain);

    void set_loop(bool loop) { loop_ = loop; }
    bool loop() const { return loop_; }
    bool ended() const { return ended_; }
    const PcmSource& source() const { return *source_; }

  private:
    static constexpr size_t kChunkFrames = 4096;
    bool fill();  // decodes more after the frames still needed; false at the very end

    std::unique_ptr<PcmSource> source_;
    double step_;  // source frames per output frame
    bool loop_;
    bool ended_ = false;
    bool source_done_ = false;
    std::array<int16_t, 2 * kChunkFrames> buffer_{};
    size_t buffered_ = 0;  // frames in buffer_
    double position_ = 0;  // in source frames, relative to buffer_[0]
};

}  // namespace nq

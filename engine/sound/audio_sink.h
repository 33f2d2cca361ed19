// Where mixed frames go. The engine asks the sink each frame how many frames it wants (the
// SDL device: enough to stay `snd_mixahead` seconds ahead of what it plays; the memory sink:
// exactly the frame's time), mixes that many and hands them over.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "sound/mixer.h"

namespace nq {

class AudioSink {
  public:
    virtual ~AudioSink() = default;
    virtual int rate() const = 0;
    virtual size_t frames_wanted(double frame_time, double mix_ahead) = 0;
    virtual void write(std::span<const StereoFrame> frames) = 0;
};

// For tests and tools: keeps every frame; wants exactly as many frames as the time passed
// (rounded on the running total, so no frame is lost or doubled over many frames).
class MemorySink final : public AudioSink {
  public:
    explicit MemorySink(int rate, size_t reserve_frames = 0) : rate_(rate) {
        frames_.reserve(reserve_frames);
    }
    int rate() const override { return rate_; }
    size_t frames_wanted(double frame_time, double mix_ahead) override;
    void write(std::span<const StereoFrame> frames) override;
    const std::vector<StereoFrame>& frames() const { return frames_; }

  private:
    int rate_;
    double clock_ = 0;
    std::vector<StereoFrame> frames_;
};

}  // namespace nq

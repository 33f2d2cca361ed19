// WAV music (music/trackNN.wav): parsed once when the track starts, then read from memory.
#include <algorithm>

#include "sound/pcm_source.h"
#include "sound/wav.h"

namespace nq {
namespace {

class WavMusicSource final : public PcmSource {
  public:
    explicit WavMusicSource(WavSound wav) : wav_(std::move(wav)) {}

    size_t read(std::span<int16_t> out) override {
        const size_t frames = std::min(out.size() / 2, wav_.samples.size() - position_);
        for (size_t i = 0; i < frames; ++i) {
            out[2 * i] = out[2 * i + 1] = wav_.samples[position_ + i];  // mixed down to mono
        }
        position_ += frames;
        return frames;
    }
    bool rewind() override {
        position_ = 0;
        return true;
    }
    int rate() const override { return wav_.rate; }
    uint64_t total_frames() const override { return wav_.samples.size(); }

  private:
    WavSound wav_;
    size_t position_ = 0;
};

}  // namespace

Result<std::unique_ptr<PcmSource>> open_wav_music(std::span<const uint8_t> bytes,
                                                  const std::string& name) {
    auto wav = parse_wav(bytes, name);
    if (!wav) return wav.error();
    return std::unique_ptr<PcmSource>(std::make_unique<WavMusicSource>(std::move(wav.value())));
}

}  // namespace nq

// The mixer: paints the sound channels and the music into 16-bit stereo frames. Deterministic
// and device-free (tests mix N frames into a buffer); the SDL device and the memory sink only
// receive what it painted. Works through a fixed paint buffer: no allocation while mixing.
#pragma once

#include <array>
#include <memory>
#include <span>

#include "sound/music_stream.h"
#include "sound/sound_channels.h"

namespace nq {

struct StereoFrame {
    int16_t left = 0, right = 0;
};

struct MixLevels {
    float volume = 0.7f;      // `volume`: sound effects
    float bgm_volume = 1.0f;  // `bgmvolume`: music
};

class Mixer {
  public:
    SoundChannels& channels() { return channels_; }
    const SoundChannels& channels() const { return channels_; }

    void set_music(std::unique_ptr<MusicStream> music) { music_ = std::move(music); }
    MusicStream* music() { return music_.get(); }
    const MusicStream* music() const { return music_.get(); }
    void set_music_paused(bool paused) { music_paused_ = paused; }
    bool music_paused() const { return music_paused_; }

    // Paints out.size() frames and moves every channel (and the music) on by as much.
    void mix(std::span<StereoFrame> out, const MixLevels& levels);

  private:
    static constexpr size_t kPaintFrames = 1024;
    void mix_chunk(std::span<StereoFrame> out, const MixLevels& levels);

    SoundChannels channels_;
    std::unique_ptr<MusicStream> music_;
    bool music_paused_ = false;
    std::array<float, 2 * kPaintFrames> paint_{};
};

}  // namespace nq

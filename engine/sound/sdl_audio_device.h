// The SDL2 audio device: its callback (on SDL's audio thread) only copies frames out of a
// lock-free single-producer ring that the engine's frame fills, and plays silence when the
// ring runs dry, so neither side ever waits for the other. No device (headless, CI) is a
// message and no sink, never a failure; SDL_AUDIODRIVER=disk works as any driver does.
#pragma once

#include <SDL.h>

#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "sound/audio_sink.h"

namespace nq {

class SdlAudioDevice final : public AudioSink {
  public:
    // nullptr (after printing why) when no device can be opened.
    static std::unique_ptr<SdlAudioDevice> open(int rate,
                                                const std::function<void(std::string_view)>& print);
    ~SdlAudioDevice() override;
    SdlAudioDevice(const SdlAudioDevice&) = delete;
    SdlAudioDevice& operator=(const SdlAudioDevice&) = delete;

    int rate() const override { return rate_; }
    size_t frames_wanted(double frame_time, double mix_ahead) override;
    void write(std::span<const StereoFrame> frames) override;
    const std::string& driver() const { return driver_; }

  private:
    SdlAudioDevice() = default;
    static void callback(void* self, Uint8* stream, int bytes);
    void fill(StereoFrame* out, size_t frames);  // audio thread

    static constexpr size_t kRingFrames = size_t(1) << 15;  // 0.74 s at 44.1 kHz
    SDL_AudioDeviceID device_ = 0;
    int rate_ = 0;
    std::string driver_;
    std::vector<StereoFrame> ring_;
    std::atomic<uint64_t> written_{0};  // frames the engine wrote (only the engine moves it)
    std::atomic<uint64_t> played_{0};   // frames the callback took (only the callback moves it)
};

}  // namespace nq

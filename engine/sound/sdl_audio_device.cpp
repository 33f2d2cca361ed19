#include "sound/sdl_audio_device.h"

#include <alsa/asoundlib.h>

#include <algorithm>

namespace nq {
namespace {

// ALSA prints every failed probe of its default device to stderr ("ALSA lib confmisc.c:855:
// cannot find card '0'", eight lines) when SDL tries it on a machine without a sound card; SDL
// reports the failure itself, once, and the engine says so.
void ignore_alsa_error(const char*, int, const char*, int, const char*, ...) {}

}  // namespace

std::unique_ptr<SdlAudioDevice> SdlAudioDevice::open(
    int rate, const std::function<void(std::string_view)>& print) {
    snd_lib_error_set_handler(&ignore_alsa_error);  // SDL loads the same libasound.so.2
    if (SDL_InitSubSystem(SDL_INIT_AUDIO) != 0) {
        print(std::string("sound: no audio (") + SDL_GetError() + "); playing silently");
        return nullptr;
    }
    std::unique_ptr<SdlAudioDevice> self(new SdlAudioDevice);
    self->ring_.resize(kRingFrames);
    SDL_AudioSpec want{};
    want.freq = rate;
    want.format = AUDIO_S16SYS;
    want.channels = 2;
    want.samples = 1024;  // 23 ms per callback at 44.1 kHz
    want.callback = &SdlAudioDevice::callback;
    want.userdata = self.get();
    SDL_AudioSpec have{};
    // No changes allowed: SDL converts to whatever the hardware wants.
    self->device_ = SDL_OpenAudioDevice(nullptr, 0, &want, &have, 0);
    if (self->device_ == 0) {
        print(std::string("sound: no audio device (") + SDL_GetError() + "); playing silently");
        SDL_QuitSubSystem(SDL_INIT_AUDIO);
        return nullptr;
    }
    self->rate_ = rate;
    const char* driver = SDL_GetCurrentAudioDriver();
    self->driver_ = driver ? driver : "?";
    SDL_PauseAudioDevice(self->device_, 0);
    return self;
}

SdlAudioDevice::~SdlAudioDevice() {
    if (device_ != 0) {
        SDL_CloseAudioDevice(device_);
        SDL_QuitSubSystem(SDL_INIT_AUDIO);
    }
}

size_t SdlAudioDevice::frames_wanted(double /*frame_time*/, double mix_ahead) {
    const uint64_t played = played_.load(std::memory_order_acquire);
    const uint64_t written = written_.load(std::memory_order_relaxed);
    const uint64_t buffered = written - played;
    const auto ahead = uint64_t(std::clamp(mix_ahead, 0.0, 0.5) * rate_);
    const uint64_t want = ahead > buffered ? ahead - buffered : 0;
    return size_t(std::min<uint64_t>(want, kRingFrames - buffered));
}

void SdlAudioDevice::write(std::span<const StereoFrame> frames) {
    uint64_t w = written_.load(std::memory_order_relaxed);
    for (const StereoFrame& f : frames) ring_[w++ % kRingFrames] = f;
    written_.store(w, std::memory_order_release);
}

void SdlAudioDevice::callback(void* self, Uint8* stream, int bytes) {
    static_cast<SdlAudioDevice*>(self)->fill(reinterpret_cast<StereoFrame*>(stream),
                                             size_t(bytes) / sizeof(StereoFrame));
}

void SdlAudioDevice::fill(StereoFrame* out, size_t frames) {
    const uint64_t written = written_.load(std::memory_order_acquire);
    uint64_t r = played_.load(std::memory_order_relaxed);
    const size_t available = size_t(std::min<uint64_t>(written - r, frames));
    for (size_t i = 0; i < available; ++i) out[i] = ring_[r++ % kRingFrames];
    std::fill(out + available, out + frames, StereoFrame{});  // ran dry: silence
    played_.store(r, std::memory_order_release);
}

}  // namespace nq

// The sounds the server's messages asked for since the engine last looked: svc_sound,
// svc_stopsound and svc_spawnstaticsound(2), in message order. The client state only records
// them (it plays nothing); the engine hands them to the sound system each frame. A fixed
// array: a frame with more sounds than it holds drops the rest and counts them.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "formats/server_message.h"

namespace nq {

struct SoundEvent {
    enum class Kind : uint8_t { Start, Stop, Static };
    Kind kind = Kind::Start;
    int entity = 0;
    int channel = 0;
    int sound = 0;          // precache index (ClientState::sound_names())
    float volume = 1;       // Start: 0..1; Static: 0..255, as on the wire
    float attenuation = 1;  // ATTN_* (the wire's byte / 64)
    Vec3 origin{};
};

class SoundEventQueue {
  public:
    static constexpr size_t kCapacity = 512;

    void push(const SoundEvent& event) {
        if (count_ < kCapacity) {
            events_[count_++] = event;
        } else {
            ++dropped_;
        }
    }
    std::span<const SoundEvent> events() const { return {events_.data(), count_}; }
    void clear() { count_ = 0; }
    uint64_t dropped() const { return dropped_; }

  private:
    std::array<SoundEvent, kCapacity> events_{};
    size_t count_ = 0;
    uint64_t dropped_ = 0;
};

}  // namespace nq

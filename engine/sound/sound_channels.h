// Quake's channel rules: four ambient channels (water, sky, slime, lava) driven by the
// listener's BSP leaf, dynamic channels per (entity, channel number) where a new sound on
// the same entity channel replaces the old one (channel 0 never replaces), and looping static
// channels. Fixed arrays: starting, stopping and painting never allocate.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "sound/sound_sample.h"
#include "sound/spatialize.h"

namespace nq {

inline constexpr int kNumAmbients = 4;  // water, sky, slime, lava (Quake's NUM_AMBIENTS)
inline constexpr size_t kMaxDynamicChannels = 128;
inline constexpr size_t kMaxStaticChannels = 256;
inline constexpr int kAmbientSilenceBelow = 8;  // Quake: a leaf volume under 8 is silence

struct SoundChannel {
    const SoundSample* sample = nullptr;  // nullptr: free
    size_t position = 0;
    int loop_start = -1;  // where playing continues after the end; -1: the channel ends
    int entity = 0;
    int entity_channel = 0;
    SoundVec3 origin{};
    float master_volume = 0;  // 0..255
    float dist_mult = 0;      // attenuation / nominal clip distance
    StereoVolume volume;      // after spatialization

    size_t frames_left() const;  // 0 when free, SIZE_MAX when looping
};

struct AmbientSettings {
    float level = 0.3f;  // ambient_level: scale of the leaf's 0..255 volumes
    float fade = 100;    // ambient_fade: volume units per second toward the target
};

class SoundChannels {
  public:
    // A dynamic sound (svc_sound, `play`, local sounds). entity_channel -1 replaces any sound
    // of the entity. Returns false when it is inaudible where the listener is (not started).
    bool start(int entity, int entity_channel, const SoundSample* sample, const SoundVec3& origin,
               float volume, float attenuation, const Listener& listener);
    void stop(int entity, int entity_channel);
    // A looping sound at a fixed place (svc_spawnstaticsound); volume 0..255. False when
    // every static channel is taken.
    bool add_static(const SoundSample* sample, const SoundVec3& origin, float volume,
                    float attenuation, const Listener& listener);
    void stop_all();  // every sound stops; static ones are forgotten, ambients fade in anew

    void set_ambient_samples(const std::array<const SoundSample*, kNumAmbients>& samples);
    // Moves each ambient volume toward leaf_levels[i] * level at `fade` units per second.
    void update_ambients(const std::array<uint8_t, kNumAmbients>& leaf_levels,
                         const AmbientSettings& settings, double frame_time);
    void spatialize_all(const Listener& listener);

    // Adds `frames` stereo frames of every channel into `mix` (interleaved L, R) with each
    // side scaled by volume / 255 * gain, and moves the channels on.
    void paint(std::span<float> mix, size_t frames, float gain);

    std::span<const SoundChannel> ambients() const { return {channels_.data(), kNumAmbients}; }
    std::span<const SoundChannel> dynamics() const {
        return {channels_.data() + kNumAmbients, kMaxDynamicChannels};
    }
    std::span<const SoundChannel> statics() const {
        return {channels_.data() + kNumAmbients + kMaxDynamicChannels, static_count_};
    }
    size_t active_count() const;

  private:
    SoundChannel* pick_dynamic(int entity, int entity_channel, int view_entity);
    static void paint_channel(SoundChannel& ch, std::span<float> mix, size_t frames, float gain);

    std::array<SoundChannel, kNumAmbients + kMaxDynamicChannels + kMaxStaticChannels> channels_{};
    std::array<float, kNumAmbients> ambient_volume_{};  // fractional, so slow fades still move
    size_t static_count_ = 0;
};

}  // namespace nq

#include "sound/sound_channels.h"

#include <algorithm>
#include <cstdint>

namespace nq {

size_t SoundChannel::frames_left() const {
    if (!sample) return 0;
    if (loop_start >= 0) return SIZE_MAX;
    return sample->length() > position ? sample->length() - position : 0;
}

SoundChannel* SoundChannels::pick_dynamic(int entity, int entity_channel, int view_entity) {
    SoundChannel* chosen = nullptr;
    size_t least_left = SIZE_MAX;
    for (size_t i = kNumAmbients; i < kNumAmbients + kMaxDynamicChannels; ++i) {
        SoundChannel& ch = channels_[i];
        // A sound on an entity's channel replaces the one playing there (channel 0 never).
        if (entity_channel != 0 && ch.entity == entity &&
            (ch.entity_channel == entity_channel || entity_channel == -1)) {
            return &ch;
        }
        // Monsters do not cut the player's own sounds short.
        if (ch.entity == view_entity && entity != view_entity && ch.sample) continue;
        if (!chosen || ch.frames_left() < least_left) {
            chosen = &ch;
            least_left = ch.frames_left();
        }
    }
    return chosen;
}

bool SoundChannels::start(int entity, int entity_channel, const SoundSample* sample,
                          const SoundVec3& origin, float volume, float attenuation,
                          const Listener& listener) {
    SoundChannel* ch = pick_dynamic(entity, entity_channel, listener.view_entity);
    if (!ch) return false;
    *ch = SoundChannel{};
    if (!sample || sample->length() == 0) return false;
    ch->origin = origin;
    ch->master_volume = volume * 255;
    ch->dist_mult = attenuation / kNominalClipDistance;
    ch->entity = entity;
    ch->entity_channel = entity_channel;
    ch->volume = entity == listener.view_entity
                     ? StereoVolume{int(ch->master_volume), int(ch->master_volume)}
                     : spatialize(origin, ch->master_volume, ch->dist_mult, listener);
    if (ch->volume.left == 0 && ch->volume.right == 0) return false;  // not audible: free
    ch->sample = sample;
    ch->loop_start = sample->loop_start;
    return true;
}

void SoundChannels::stop(int entity, int entity_channel) {
    for (size_t i = kNumAmbients; i < kNumAmbients + kMaxDynamicChannels; ++i) {
        SoundChannel& ch = channels_[i];
        if (ch.entity == entity && ch.entity_channel == entity_channel) ch = SoundChannel{};
    }
}

bool SoundChannels::add_static(const SoundSample* sample, const SoundVec3& origin, float volume,
                               float attenuation, const Listener& listener) {
    if (!sample || sample->length() == 0) return true;  // nothing to hear, not an overflow
    if (static_count_ == kMaxStaticChannels) return false;
    SoundChannel& ch = channels_[kNumAmbients + kMaxDynamicChannels + static_count_++];
    ch = SoundChannel{};
    ch.sample = sample;
    // Quake refuses static sounds without a cue point; LibreQuake's WAVs have none, so a
    // static sound without one loops from its start.
    ch.loop_start = std::max(sample->loop_start, 0);
    ch.origin = origin;
    ch.master_volume = volume;
    ch.dist_mult = attenuation / kNominalClipDistance;
    ch.volume = spatialize(origin, ch.master_volume, ch.dist_mult, listener);
    return true;
}

void SoundChannels::stop_all() {
    for (size_t i = 0; i < channels_.size(); ++i) {
        SoundChannel& ch = channels_[i];
        SoundChannel cleared;
        if (i < kNumAmbients) {  // ambients keep their sample, silent until the next update
            cleared.sample = ch.sample;
            cleared.loop_start = ch.loop_start;
        }
        ch = cleared;
    }
    ambient_volume_.fill(0);
    static_count_ = 0;
}

void SoundChannels::set_ambient_samples(
    const std::array<const SoundSample*, kNumAmbients>& samples) {
    for (int i = 0; i < kNumAmbients; ++i) {
        SoundChannel& ch = channels_[size_t(i)];
        if (ch.sample == samples[size_t(i)]) continue;
        ch = SoundChannel{};
        ch.sample =
            samples[size_t(i)] && samples[size_t(i)]->length() ? samples[size_t(i)] : nullptr;
        ch.loop_start = ch.sample ? std::max(ch.sample->loop_start, 0) : -1;
        ambient_volume_[size_t(i)] = 0;
    }
}

void SoundChannels::update_ambients(const std::array<uint8_t, kNumAmbients>& leaf_levels,
                                    const AmbientSettings& settings, double frame_time) {
    const auto step = float(frame_time * double(settings.fade));
    for (int i = 0; i < kNumAmbients; ++i) {
        float target = settings.level * float(leaf_levels[size_t(i)]);
        if (target < kAmbientSilenceBelow) target = 0;
        float& v = ambient_volume_[size_t(i)];
        v = v < target ? std::min(v + step, target) : std::max(v - step, target);
        SoundChannel& ch = channels_[size_t(i)];
        ch.master_volume = v;
        ch.volume = {int(v), int(v)};
    }
}

void SoundChannels::spatialize_all(const Listener& listener) {
    for (size_t i = kNumAmbients; i < kNumAmbients + kMaxDynamicChannels + static_count_; ++i) {
        SoundChannel& ch = channels_[i];
        if (!ch.sample) continue;
        if (ch.entity == listener.view_entity && i < kNumAmbients + kMaxDynamicChannels) {
            ch.volume = {int(ch.master_volume), int(ch.master_volume)};
        } else {
            ch.volume = spatialize(ch.origin, ch.master_volume, ch.dist_mult, listener);
        }
    }
}

void SoundChannels::paint_channel(SoundChannel& ch, std::span<float> mix, size_t frames,
                                  float gain) {
    const float left = float(ch.volume.left) / 255.0f * gain;
    const float right = float(ch.volume.right) / 255.0f * gain;
    const int16_t* data = ch.sample->frames.data();
    const size_t length = ch.sample->length();
    size_t pos = ch.position;
    for (size_t i = 0; i < frames; ++i) {
        if (pos >= length) {
            if (ch.loop_start < 0) {
                ch = SoundChannel{};  // a one-shot sound ended: the channel is free
                return;
            }
            pos = size_t(ch.loop_start);
        }
        const float s = float(data[pos++]);
        mix[2 * i] += s * left;
        mix[2 * i + 1] += s * right;
    }
    ch.position = pos;
    // A one-shot that ended exactly at the buffer's end is freed now, not a buffer later.
    if (ch.loop_start < 0 && pos >= length) ch = SoundChannel{};
}

void SoundChannels::paint(std::span<float> mix, size_t frames, float gain) {
    for (size_t i = 0; i < kNumAmbients + kMaxDynamicChannels + static_count_; ++i) {
        SoundChannel& ch = channels_[i];
        if (ch.sample) paint_channel(ch, mix, frames, gain);
    }
}

size_t SoundChannels::active_count() const {
    return size_t(std::count_if(channels_.begin(), channels_.end(),
                                [](const SoundChannel& ch) { return ch.sample != nullptr; }));
}

}  // namespace nq

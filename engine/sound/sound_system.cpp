#include "sound/sound_system.h"

#include <algorithm>
#include <cstdio>

#include "formats/bsp.h"
#include "sound/wav.h"

namespace nq {
namespace {

// Quake's ambient sounds by leaf ambient index; slime and lava have none in Quake either.
constexpr std::array<const char*, kNumAmbients> kAmbientSounds = {
    "ambience/water1.wav", "ambience/wind2.wav", nullptr, nullptr};

bool has_extension(const std::string& name) {
    const size_t slash = name.find_last_of('/');
    const size_t dot = name.find_last_of('.');
    return dot != std::string::npos && (slash == std::string::npos || dot > slash);
}

}  // namespace

SoundSystem::SoundSystem(std::unique_ptr<AudioSink> sink, SoundFileReader reader,
                         SoundPrinter print)
    : sink_(std::move(sink)), reader_(std::move(reader)), print_(std::move(print)) {
    std::array<const SoundSample*, kNumAmbients> ambients{};
    for (size_t i = 0; i < kNumAmbients; ++i) {
        if (kAmbientSounds[i]) ambients[i] = load(kAmbientSounds[i]);
    }
    mixer_.channels().set_ambient_samples(ambients);
}

void SoundSystem::warn_once(const std::string& key, std::string_view text) {
    if (warned_.insert(key).second) print_(text);
}

const SoundSample* SoundSystem::load(const std::string& name) {
    if (name.empty()) return nullptr;
    if (auto it = cache_.find(name); it != cache_.end()) return it->second.get();
    std::unique_ptr<SoundSample> sample;
    const std::string path = "sound/" + name;
    auto bytes = reader_(path);
    if (!bytes) {
        warn_once(name, "warning: sound " + path + " not found: " + bytes.error().message);
    } else if (auto wav = parse_wav(*bytes, path); !wav) {
        warn_once(name, "warning: sound " + wav.error().to_string() + "; playing silence");
    } else {
        sample = std::make_unique<SoundSample>(resample(*wav, rate()));
    }
    return cache_.emplace(name, std::move(sample)).first->second.get();
}

void SoundSystem::precache(std::span<const std::string> names) {
    precached_.assign(names.size(), nullptr);
    for (size_t i = 1; i < names.size(); ++i) precached_[i] = load(names[i]);
}

const SoundSample* SoundSystem::precached(int index) const {
    if (index <= 0 || size_t(index) >= precached_.size()) return nullptr;
    return precached_[size_t(index)];
}

void SoundSystem::start_sound(int entity, int channel, int sound_index, const SoundVec3& origin,
                              float volume, float attenuation) {
    start_sound(entity, channel, precached(sound_index), origin, volume, attenuation);
}

void SoundSystem::start_sound(int entity, int channel, const SoundSample* sample,
                              const SoundVec3& origin, float volume, float attenuation) {
    if (muted_ || !sample) return;
    mixer_.channels().start(entity, channel, sample, origin, volume, attenuation, listener_);
}

void SoundSystem::local_sound(const std::string& name) {
    start_sound(listener_.view_entity, -1, load(name), SoundVec3{}, 1.0f, 1.0f);
}

void SoundSystem::play(const std::string& name) {
    const std::string file = has_extension(name) ? name : name + ".wav";
    start_sound(play_entity_++, 0, load(file), listener_.origin, 1.0f, 1.0f);
}

void SoundSystem::stop_sound(int entity, int channel) {
    mixer_.channels().stop(entity, channel);
}

void SoundSystem::add_static_sound(int sound_index, const SoundVec3& origin, float volume,
                                   float attenuation) {
    if (!mixer_.channels().add_static(precached(sound_index), origin, volume, attenuation,
                                      listener_)) {
        warn_once("#static-overflow", "warning: too many static sounds; the rest are silent");
    }
}

void SoundSystem::stop_all_sounds() {
    mixer_.channels().stop_all();
}

void SoundSystem::play_cd_track(int track, bool loop) {
    if (track <= 0) return stop_music();  // track 0 (or none): no music, as on the CD
    char name[16];
    std::snprintf(name, sizeof name, "track%02d", track);
    play_music(name, loop);
}

bool SoundSystem::play_music(const std::string& name, bool loop) {
    std::string base = name.rfind("music/", 0) == 0 ? name : "music/" + name;
    if (music_playing() && music_name_ == base && mixer_.music()->loop() == loop) return true;
    stop_music();
    std::vector<std::string> candidates;
    if (has_extension(base)) {
        candidates = {base};
    } else {
        candidates = {base + ".ogg", base + ".wav"};
    }
    for (const std::string& path : candidates) {
        auto bytes = reader_(path);
        if (!bytes) continue;
        const bool ogg = path.ends_with(".ogg");
        auto source =
            ogg ? open_ogg(std::move(bytes.value()), path) : open_wav_music(bytes.value(), path);
        if (!source) {
            print_("music: " + source.error().to_string());
            return false;
        }
        mixer_.set_music(std::make_unique<MusicStream>(std::move(source.value()), rate(), loop));
        mixer_.set_music_paused(false);
        music_name_ = base;
        return true;
    }
    warn_once("#music:" + base, "music: " + base + " not found (.ogg or .wav); no music");
    return false;
}

void SoundSystem::stop_music() {
    mixer_.set_music(nullptr);
    music_name_.clear();
}

void SoundSystem::set_music_loop(bool loop) {
    if (MusicStream* music = mixer_.music()) music->set_loop(loop);
}

bool SoundSystem::music_playing() const {
    const MusicStream* music = mixer_.music();
    return music && !music->ended();
}

void SoundSystem::set_muted(bool muted) {
    if (muted && !muted_) stop_all_sounds();
    muted_ = muted;
}

void SoundSystem::update_ambients(double frame_time, const AmbientSettings& settings) {
    std::array<uint8_t, kNumAmbients> levels{};
    if (world_ && !world_->leafs.empty()) {
        const uint32_t leaf = leaf_at(*world_, listener_.origin);
        if (leaf < world_->leafs.size()) levels = world_->leafs[leaf].ambient_levels;
    }
    mixer_.channels().update_ambients(levels, settings, frame_time);
}

void SoundSystem::update(double frame_time, bool paused, const SoundSettings& settings) {
    if (!paused) {
        update_ambients(frame_time, settings.ambient);
        mixer_.channels().spatialize_all(listener_);
    }
    size_t wanted = sink_->frames_wanted(frame_time, settings.mix_ahead);
    while (wanted > 0) {
        const size_t n = std::min(wanted, scratch_.size());
        std::span<StereoFrame> out(scratch_.data(), n);
        if (paused || muted_) {
            std::fill(out.begin(), out.end(), StereoFrame{});
        } else {
            mixer_.mix(out, settings.levels);
        }
        sink_->write(out);
        wanted -= n;
    }
}

}  // namespace nq

// The sound system as the engine and the client see it (Quake's S_* functions): loading
// sounds at precache time, starting and stopping them, static and ambient sounds, the CD
// track, and once per frame update(): ambient fades, spatialization against the listener,
// mixing what the sink wants. Its output is an AudioSink: the SDL device in the engine, a
// MemorySink in tests. Single-threaded: only the sink's device callback runs elsewhere.
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "common/result.h"
#include "sound/audio_sink.h"
#include "sound/mixer.h"

namespace nq {

struct Bsp;

using SoundFileReader = std::function<Result<std::vector<uint8_t>>(const std::string& path)>;
using SoundPrinter = std::function<void(std::string_view)>;

// Values of the sound cvars, copied in each frame.
struct SoundSettings {
    MixLevels levels;
    AmbientSettings ambient;
    double mix_ahead = 0.1;  // snd_mixahead
};

inline constexpr int kOutputRate = 44100;

class SoundSystem {
  public:
    SoundSystem(std::unique_ptr<AudioSink> sink, SoundFileReader reader, SoundPrinter print);

    int rate() const { return sink_->rate(); }
    AudioSink& sink() { return *sink_; }
    const Mixer& mixer() const { return mixer_; }

    // ---- loading (Quake's S_PrecacheSound): "weapons/rocket1i.wav" is sound/weapons/...
    // A missing or broken file warns once and is silence.
    const SoundSample* load(const std::string& name);
    // The client's precache list (index 0 is unused); loads every sound now.
    void precache(std::span<const std::string> names);
    const SoundSample* precached(int index) const;

    // ---- sounds
    void start_sound(int entity, int channel, int sound_index, const SoundVec3& origin,
                     float volume, float attenuation);
    void start_sound(int entity, int channel, const SoundSample* sample, const SoundVec3& origin,
                     float volume, float attenuation);
    void local_sound(const std::string& name);  // menus, pickups: full volume, both ears
    void play(const std::string& name);         // the `play` command: at the listener
    void stop_sound(int entity, int channel);
    void add_static_sound(int sound_index, const SoundVec3& origin, float volume,
                          float attenuation);
    void stop_all_sounds();  // a new level, a demo's end: nothing carries over
    void set_world(const Bsp* world) { world_ = world; }
    void set_listener(const Listener& listener) { listener_ = listener; }
    const Listener& listener() const { return listener_; }

    // ---- music (CD tracks as music/trackNN.ogg or .wav)
    void play_cd_track(int track, bool loop);
    // "track03" or "music/track03.ogg": tries .ogg then .wav when no extension is given.
    bool play_music(const std::string& name, bool loop);
    void stop_music();
    void pause_music(bool paused) { mixer_.set_music_paused(paused); }
    void set_music_loop(bool loop);
    bool music_playing() const;
    const std::string& music_name() const { return music_name_; }

    // ---- the frame
    // Muted (nosound 1, a silent timedemo): no new sounds start and silence is mixed.
    void set_muted(bool muted);
    bool muted() const { return muted_; }
    // Moves ambients toward the listener's leaf, respatializes, and mixes what the sink wants
    // for `frame_time`. Paused: the sink gets silence and no sound moves on.
    void update(double frame_time, bool paused, const SoundSettings& settings);

  private:
    void update_ambients(double frame_time, const AmbientSettings& settings);
    void warn_once(const std::string& key, std::string_view text);

    std::unique_ptr<AudioSink> sink_;
    SoundFileReader reader_;
    SoundPrinter print_;
    Mixer mixer_;
    std::unordered_map<std::string, std::unique_ptr<SoundSample>> cache_;  // nullptr: missing
    std::vector<const SoundSample*> precached_;
    std::unordered_set<std::string> warned_;
    const Bsp* world_ = nullptr;
    Listener listener_;
    bool muted_ = false;
    int play_entity_ = 345;  // `play` gives each sound an entity of its own (Quake's hash)
    std::string music_name_;
    std::array<StereoFrame, 1024> scratch_{};
};

}  // namespace nq

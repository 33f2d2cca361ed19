// The sound system's cvars and console commands, with Quake's and QuakeSpasm's names and
// defaults: volume, bgmvolume, nosound, snd_mixahead, ambient_level, ambient_fade,
// timedemo_sound, snd_show; play, playvol, stopsound, soundlist, soundinfo, music,
// music_stop, music_pause, music_resume, music_loop, cd.
#pragma once

#include <functional>

#include "host/command_system.h"
#include "host/cvar_registry.h"
#include "sound/sound_system.h"

namespace nq {

struct SoundCvars {
    Cvar* volume = nullptr;
    Cvar* bgm_volume = nullptr;
    Cvar* nosound = nullptr;
    Cvar* mix_ahead = nullptr;
    Cvar* ambient_level = nullptr;
    Cvar* ambient_fade = nullptr;
    Cvar* timedemo_sound = nullptr;
    Cvar* show = nullptr;
};

SoundCvars register_sound_cvars(CvarRegistry& cvars);
SoundSettings sound_settings(const SoundCvars& cvars);

// The commands exist with sound off too (`-nosound`): `sound` then returns nullptr and they
// say so instead of failing scripts.
using SoundGetter = std::function<SoundSystem*()>;
void register_sound_commands(CommandSystem& commands, SoundGetter sound);

// The snd_show line: the sounds playing, as Quake lists them (volume, name index).
std::string describe_active_sounds(const SoundSystem& sound);

}  // namespace nq

#include "sound/sound_commands.h"

#include <cstdlib>
#include <string>

namespace nq {
namespace {

Cvar* numeric(CvarRegistry& cvars, const char* name, const char* value, uint32_t flags,
              const char* description, float min, float max) {
    return cvars.register_cvar({name, value, flags, description, min, max});
}

void add_music_commands(CommandSystem& c, const SoundGetter& sound) {
    auto with_sound = [&c, sound](auto&& fn) {
        return [&c, sound, fn](const CommandArgs& a) {
            if (SoundSystem* s = sound()) return fn(*s, a);
            c.print("sound is off");
        };
    };
    c.add_command("music", with_sound([&c](SoundSystem& s, const CommandArgs& a) {
                      if (a.argc() < 2) {
                          const std::string& n = s.music_name();
                          return c.print(n.empty() ? "no music" : "playing " + n);
                      }
                      s.play_music(a.argv(1), true);
                  }),
                  "play music/NAME (.ogg or .wav), looping: music track03");
    c.add_command("music_stop",
                  with_sound([](SoundSystem& s, const CommandArgs&) { s.stop_music(); }),
                  "stop the music");
    c.add_command("music_pause",
                  with_sound([](SoundSystem& s, const CommandArgs&) { s.pause_music(true); }),
                  "pause the music");
    c.add_command("music_resume",
                  with_sound([](SoundSystem& s, const CommandArgs&) { s.pause_music(false); }),
                  "resume the paused music");
    c.add_command("music_loop", with_sound([&c](SoundSystem& s, const CommandArgs& a) {
                      const MusicStream* m = s.mixer().music();
                      bool loop = m ? m->loop() : true;
                      if (a.argc() < 2 || a.argv(1) == "toggle") {
                          if (a.argc() >= 2) loop = !loop;
                      } else {
                          loop = std::atoi(a.argv(1).c_str()) != 0;
                      }
                      s.set_music_loop(loop);
                      c.print(loop ? "music loops" : "music plays once");
                  }),
                  "music_loop [0|1|toggle]: whether the music starts over at its end");
    c.add_command("cd", with_sound([&c](SoundSystem& s, const CommandArgs& a) {
                      const std::string verb = a.argc() > 1 ? a.argv(1) : "info";
                      const int track = a.argc() > 2 ? std::atoi(a.argv(2).c_str()) : 0;
                      if (verb == "play" || verb == "loop") {
                          s.play_cd_track(track, verb == "loop");
                      } else if (verb == "stop") {
                          s.stop_music();
                      } else if (verb == "pause") {
                          s.pause_music(true);
                      } else if (verb == "resume") {
                          s.pause_music(false);
                      } else {
                          const std::string& n = s.music_name();
                          c.print(n.empty() ? "cd: no track" : "cd: playing " + n);
                      }
                  }),
                  "cd play|loop N, cd stop|pause|resume|info: CD tracks as music/trackNN");
}

void add_effect_commands(CommandSystem& c, const SoundGetter& sound) {
    c.add_command(
        "play",
        [&c, sound](const CommandArgs& a) {
            SoundSystem* s = sound();
            if (!s) return c.print("sound is off");
            for (size_t i = 1; i < a.argc(); ++i) s->play(a.argv(i));
        },
        "play sound/NAME[.wav] where the listener is: play misc/menu1");
    c.add_command(
        "playvol",
        [&c, sound](const CommandArgs& a) {
            SoundSystem* s = sound();
            if (!s) return c.print("sound is off");
            if (a.argc() < 3) return c.print("usage: playvol <sound> <volume 0..1> ...");
            for (size_t i = 1; i + 1 < a.argc(); i += 2) {
                std::string name = a.argv(i);
                if (name.find('.') == std::string::npos) name += ".wav";
                s->start_sound(0, 0, s->load(name), s->listener().origin,
                               float(std::atof(a.argv(i + 1).c_str())), 1.0f);
            }
        },
        "play sounds at a volume: playvol misc/menu1 0.5");
    c.add_command(
        "stopsound",
        [sound](const CommandArgs&) {
            if (SoundSystem* s = sound()) s->stop_all_sounds();
        },
        "stop every sound");
    c.add_command(
        "soundinfo",
        [&c, sound](const CommandArgs&) {
            SoundSystem* s = sound();
            if (!s) return c.print("sound is off: no device, no mixer");
            c.print(std::to_string(s->rate()) + " Hz stereo, 16 bit; " +
                    std::to_string(s->mixer().channels().active_count()) + " channels playing" +
                    (s->muted() ? " (muted)" : ""));
        },
        "the sound output and how many channels play");
}

}  // namespace

SoundCvars register_sound_cvars(CvarRegistry& cvars) {
    SoundCvars v;
    v.volume = numeric(cvars, "volume", "0.7", kCvarArchive, "sound effects volume", 0, 1);
    v.bgm_volume = numeric(cvars, "bgmvolume", "1", kCvarArchive, "music volume", 0, 1);
    v.nosound = numeric(cvars, "nosound", "0", 0, "1: no sound is started or mixed", 0, 1);
    v.mix_ahead = numeric(cvars, "snd_mixahead", "0.1", kCvarArchive,
                          "seconds of sound mixed ahead of the device", 0.01f, 0.5f);
    v.ambient_level = numeric(cvars, "ambient_level", "0.3", 0,
                              "scale of the leaf ambient sounds (water, wind)", 0, 1);
    v.ambient_fade = numeric(cvars, "ambient_fade", "100", 0,
                             "ambient volume change per second (0..255 units)", 0, 1000);
    v.timedemo_sound = numeric(cvars, "timedemo_sound", "0", 0,
                               "1: a timedemo is heard (0: silent, as fast as it runs)", 0, 1);
    v.show = numeric(cvars, "snd_show", "0", 0, "1: print the sounds playing each frame", 0, 1);
    return v;
}

SoundSettings sound_settings(const SoundCvars& cvars) {
    SoundSettings s;
    s.levels.volume = cvars.volume->value();
    s.levels.bgm_volume = cvars.bgm_volume->value();
    s.ambient.level = cvars.ambient_level->value();
    s.ambient.fade = cvars.ambient_fade->value();
    s.mix_ahead = cvars.mix_ahead->value();
    return s;
}

void register_sound_commands(CommandSystem& commands, SoundGetter sound) {
    add_effect_commands(commands, sound);
    add_music_commands(commands, sound);
}

std::string describe_active_sounds(const SoundSystem& sound) {
    std::string text;
    int total = 0;
    auto list = [&](std::span<const SoundChannel> channels) {
        for (const SoundChannel& ch : channels) {
            if (!ch.sample || (ch.volume.left == 0 && ch.volume.right == 0)) continue;
            text += std::to_string(ch.volume.left) + " " + std::to_string(ch.volume.right) +
                    " entity " + std::to_string(ch.entity) + "\n";
            ++total;
        }
    };
    list(sound.mixer().channels().ambients());
    list(sound.mixer().channels().dynamics());
    list(sound.mixer().channels().statics());
    return text + "----(" + std::to_string(total) + ")----";
}

}  // namespace nq

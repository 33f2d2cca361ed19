// The engine's sound wing: the sound cvars and commands, the output opened the first frame
// sound is wanted (never with -nosound; a machine without a device says so once and stays
// silent), and each frame what the running demo or game's client recorded handed to the sound
// system with the listener. The engine holds one and calls update() once a frame; nothing
// else of the engine reaches into it.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string_view>

#include "host/host_core.h"
#include "sound/audio_sink.h"
#include "sound/client_sound_feed.h"
#include "sound/sound_commands.h"
#include "sound/sound_system.h"

namespace nq {

struct Bsp;

// What update() needs to know of the frame.
struct SoundFrame {
    ClientState* client = nullptr;  // the demo's or game's client; null when none runs
    uint32_t session = 0;           // changes when a new demo or game starts (a new client)
    bool timedemo = false;          // a timedemo plays (silent unless timedemo_sound 1)
    bool paused = false;
    const Bsp* world = nullptr;  // the level, for its leafs' ambient sounds
    Listener listener;           // the view drawn
};

class GameSound {
  public:
    using Printer = std::function<void(std::string_view)>;
    // Opens the output at `rate` and says which it is (SDL's device in the engine, a
    // MemorySink in tests); nullptr, having said why, when there is none.
    using SinkOpener = std::function<std::unique_ptr<AudioSink>(int rate, const Printer& print)>;

    // Registers the cvars and commands. `nosound`: -nosound, no output ever opened.
    GameSound(HostCore& host, bool nosound, Printer print, SinkOpener open = open_sdl_sink);
    GameSound(const GameSound&) = delete;  // its commands hold `this`
    GameSound& operator=(const GameSound&) = delete;

    // Where sound files come from (the game data); read when a level's sounds load.
    void set_reader(SoundFileReader reader) { reader_ = std::move(reader); }

    void update(double frame_time, const SoundFrame& frame);

    // nullptr until the output is open (and for good with -nosound or no device).
    SoundSystem* system() { return system_.get(); }

    // SDL's device through SdlAudioDevice, and a line naming its driver.
    static std::unique_ptr<AudioSink> open_sdl_sink(int rate, const Printer& print);

  private:
    void open();

    Printer print_;
    SinkOpener open_sink_;
    SoundFileReader reader_;
    SoundCvars cvars_;
    std::unique_ptr<SoundSystem> system_;
    ClientSoundFeed feed_;
    bool disabled_ = false;  // -nosound, or no output could be opened
    uint32_t session_ = 0;
    bool was_running_ = false;
};

}  // namespace nq

#include "sound/game_sound.h"

#include "sound/sdl_audio_device.h"

namespace nq {

GameSound::GameSound(HostCore& host, bool nosound, Printer print, SinkOpener open)
    : print_(std::move(print)), open_sink_(std::move(open)) {
    cvars_ = register_sound_cvars(host.cvars());
    register_sound_commands(host.commands(), [this] { return system_.get(); });
    if (nosound) {
        disabled_ = true;
        print_("sound: off (-nosound)");
    }
}

std::unique_ptr<AudioSink> GameSound::open_sdl_sink(int rate, const Printer& print) {
    auto device = SdlAudioDevice::open(rate, print);
    if (!device) return nullptr;
    print("sound: " + std::to_string(device->rate()) + " Hz stereo through SDL's \"" +
          device->driver() + "\" driver");
    return device;
}

void GameSound::open() {
    auto sink = open_sink_(kOutputRate, print_);
    if (!sink) {
        disabled_ = true;  // said why; the engine goes on in silence
        return;
    }
    SoundFileReader reader = reader_;
    if (!reader) {
        reader = [](const std::string& path) -> Result<std::vector<uint8_t>> {
            return Error{path, 0, "no game data mounted"};
        };
    }
    system_ = std::make_unique<SoundSystem>(std::move(sink), std::move(reader), print_);
}

void GameSound::update(double frame_time, const SoundFrame& frame) {
    const bool nosound = cvars_.nosound->value() != 0;
    if (!system_ && (disabled_ || nosound)) return;  // costs nothing
    if (!system_) open();
    if (!system_) return;
    const bool running = frame.client != nullptr;
    if (running && frame.session != session_) {
        session_ = frame.session;  // a new demo or game: a new client
        feed_.reset();
    }
    if (!running && was_running_) {  // it ended: Quake's disconnect stops everything
        system_->stop_all_sounds();
        system_->stop_music();
    }
    was_running_ = running;
    const bool silent_timedemo = frame.timedemo && cvars_.timedemo_sound->value() == 0;
    system_->set_muted(nosound || silent_timedemo);
    if (running) {
        system_->set_world(frame.world);
        feed_.feed(*frame.client, *system_, frame.listener);
    } else {
        system_->set_world(nullptr);
    }
    system_->update(frame_time, frame.paused, sound_settings(cvars_));
    if (cvars_.show->value() != 0) print_(describe_active_sounds(*system_));
}

}  // namespace nq

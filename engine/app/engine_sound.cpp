// The engine's side of sound: cvars and commands, opening the device when sound is first
// wanted, and each frame handing the client's sounds and the listener (the view drawn) to the
// sound system, which mixes what the device wants.
#include "app/engine.h"
#include "sound/sdl_audio_device.h"

namespace nq {

void Engine::register_sound() {
    sound_cvars_ = register_sound_cvars(host_.cvars());
    register_sound_commands(host_.commands(), [this] { return sound_.get(); });
    if (command_line_.has("-nosound")) {
        sound_disabled_ = true;
        print("sound: off (-nosound)");
    }
}

void Engine::open_sound() {
    auto device = SdlAudioDevice::open(kOutputRate, [this](std::string_view t) { print(t); });
    if (!device) {
        sound_disabled_ = true;  // said why; the engine goes on in silence
        return;
    }
    print("sound: " + std::to_string(device->rate()) + " Hz stereo through SDL's \"" +
          device->driver() + "\" driver");
    const Vfs* vfs = vfs_ ? &*vfs_ : nullptr;
    SoundFileReader reader = [vfs](const std::string& path) -> Result<std::vector<uint8_t>> {
        if (!vfs) return Error{path, 0, "no game data mounted"};
        return vfs->read(path);
    };
    sound_ = std::make_unique<SoundSystem>(std::move(device), std::move(reader),
                                           [this](std::string_view t) { print(t); });
}

void Engine::update_sound(double frame_time) {
    const bool nosound = sound_cvars_.nosound->value() != 0;
    if (!sound_ && (sound_disabled_ || nosound)) return;  // costs nothing
    if (!sound_) open_sound();
    if (!sound_) return;
    const bool active = demo_->active();
    if (active && demo_->starts() != sound_demo_starts_) {
        sound_demo_starts_ = demo_->starts();  // a new demo or game: a new client
        sound_feed_.reset();
    }
    if (!active && sound_demo_active_) {  // it ended: Quake's disconnect stops everything
        sound_->stop_all_sounds();
        sound_->stop_music();
    }
    sound_demo_active_ = active;
    const bool silent_timedemo =
        active && demo_->mode() == DemoMode::TimeDemo && sound_cvars_.timedemo_sound->value() == 0;
    sound_->set_muted(nosound || silent_timedemo);
    if (active) {
        sound_->set_world(demo_->level().world_bsp());
        sound_feed_.feed(demo_->client(), *sound_, listener_);
    } else {
        sound_->set_world(nullptr);
    }
    sound_->update(frame_time, demo_->paused(), sound_settings(sound_cvars_));
    if (sound_cvars_.show->value() != 0) print(describe_active_sounds(*sound_));
}

}  // namespace nq

// What the sound wing (sound/game_sound.h) is told of the frame: the running demo or game's
// client, whether a new one began, a timedemo, the pause, the level and the view drawn.
#include "app/engine.h"

namespace nq {

void Engine::update_sound(double frame_time) {
    SoundFrame frame;
    if (demo_->active()) {
        frame.client = &demo_->client();
        frame.session = demo_->starts();
        frame.timedemo = demo_->mode() == DemoMode::TimeDemo;
        frame.world = demo_->level().world_bsp();
    }
    frame.paused = demo_->paused();
    frame.listener = frames_->listener();
    sound_->update(frame_time, frame);
}

}  // namespace nq

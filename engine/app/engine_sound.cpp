// What the sound wing (sound/game_sound.h) is told of the frame: the running demo or game's
// client, whether a new one began, a timedemo, the pause, the level and the view drawn.
#include "app/engine.h"

namespace nq {

void Engine::update_sound(double frame_time) {
    SoundFrame frame;
    if (sessions_->session().active()) {
        frame.client = &sessions_->session().client();
        frame.session = sessions_->session().starts();
        frame.timedemo = sessions_->session().mode() == DemoMode::TimeDemo;
        frame.world = sessions_->session().level().world_bsp();
    }
    frame.paused = sessions_->session().paused();
    frame.listener = frames_->listener();
    sound_->update(frame_time, frame);
}

}  // namespace nq

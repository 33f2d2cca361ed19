// vid_width, vid_height, vid_fullscreen and vid_restart, as QuakeSpasm has them: the cvars
// say the mode, vid_restart applies it. A size or window mode given on the command line
// (-width, -height, -window, -fullscreen) locks the mode for the whole run, so a config's
// `vid_restart` (LibreQuake's default.cfg asks for 1280x720) cannot override what a script or
// a benchmark asked for. Headless (SDL's offscreen driver) the mode stays what it opened with.
#include "app/engine.h"

namespace nq {

bool Engine::video_mode_locked() const {
    return options_.width || options_.height || options_.fullscreen;
}

void Engine::register_video_commands() {
    CvarRegistry& cvars = host_.cvars();
    const float largest = float(kMaxWindowDimension);
    cvars_.vid_width =
        cvars.register_cvar({"vid_width", std::to_string(window_->drawable_width()), kCvarArchive,
                             "window width for vid_restart", 320.0f, largest});
    cvars_.vid_height =
        cvars.register_cvar({"vid_height", std::to_string(window_->drawable_height()), kCvarArchive,
                             "window height for vid_restart", 200.0f, largest});
    cvars_.vid_fullscreen =
        cvars.register_cvar({"vid_fullscreen", options_.fullscreen.value_or(false) ? "1" : "0",
                             kCvarArchive, "1: fullscreen after vid_restart", 0.0f, 1.0f});
    host_.commands().add_command(
        "vid_restart", [this](const CommandArgs&) { restart_video(); },
        "vid_restart: apply vid_width, vid_height and vid_fullscreen");
}

void Engine::restart_video() {
    if (video_mode_locked()) {
        return print(
            "vid_restart: the command line's -width/-height/-window/-fullscreen keep "
            "the mode");
    }
    if (!window_->can_change_size()) {
        return print(
            "vid_restart: this video driver cannot change the mode after start-up "
            "(use -width and -height)");
    }
    const int width = cvars_.vid_width->integer();
    const int height = cvars_.vid_height->integer();
    if (std::string why = window_->set_fullscreen(cvars_.vid_fullscreen->value() != 0);
        !why.empty()) {
        print("vid_restart: " + why);
    }
    window_->set_window_size(width, height);
    console_->set_screen_size(window_->drawable_width(), window_->drawable_height());
    print("video mode " + std::to_string(window_->drawable_width()) + "x" +
          std::to_string(window_->drawable_height()));
}

}  // namespace nq

#include "app/shell/screen.h"

#include <epoxy/gl.h>

#include "video/resident_libraries.h"

namespace nq {

Result<std::unique_ptr<Screen>> Screen::open(const LaunchOptions& options, PrintFn print) {
    VideoOptions video;
    video.width = options.width.value_or(640);
    video.height = options.height.value_or(480);
    video.fullscreen = options.fullscreen.value_or(false);
    auto window = VideoWindow::create(video);
    if (!window) {
        return Error{"video", 0,
                     "cannot open a window: " + window.error().message +
                         " (headless? try SDL_VIDEODRIVER=offscreen)"};
    }
    keep_loaded_libraries_resident();  // the GL driver, not plugins: see resident_libraries.h
    return std::unique_ptr<Screen>(
        new Screen(std::move(window.value()), options, std::move(print)));
}

Screen::Screen(VideoWindow window, const LaunchOptions& options, PrintFn print)
    : window_(std::move(window)), options_(options), print_(std::move(print)) {
    print_("GL_RENDERER: " + gl_info().renderer + "\nGL_VERSION: " + gl_info().version);
    if (auto gamma = GammaPass::create()) {
        gamma_pass_.emplace(std::move(gamma.value()));
    } else {
        print_("gamma: " + gamma.error().message);
    }
    // Occlusion culling samples pixel centres; a multisampled screen covers other points of
    // the pixel too.
    GLint samples = 0;
    glGetIntegerv(GL_SAMPLES, &samples);
    multisampled_ = samples > 1;
    if (multisampled_) print_("multisampled screen: r_occlusion has no effect");
}

Screen::~Screen() {
    gamma_pass_.reset();  // GL objects and the throttle's fences go while the context is there
    throttle_.release();
}

void Screen::set_relative_mouse(bool on) {
    if (on != relative_mouse_) window_.set_relative_mouse(on);
    relative_mouse_ = on;
}

void Screen::apply_levels(const ScreenLevels& levels) {
    if (gamma_pass_) gamma_pass_->apply(levels, width(), height());
}

void Screen::swap() {
    throttle_.before_swap();
    window_.swap();
    throttle_.after_swap();
}

bool Screen::mode_locked() const {
    return options_.width || options_.height || options_.fullscreen;
}

void Screen::register_commands(HostCore& host, std::function<void()> resized) {
    resized_ = std::move(resized);
    CvarRegistry& cvars = host.cvars();
    const float largest = float(kMaxWindowDimension);
    vid_width_ = cvars.register_cvar({"vid_width", std::to_string(width()), kCvarArchive,
                                      "window width for vid_restart", 320.0f, largest});
    vid_height_ = cvars.register_cvar({"vid_height", std::to_string(height()), kCvarArchive,
                                       "window height for vid_restart", 200.0f, largest});
    vid_fullscreen_ =
        cvars.register_cvar({"vid_fullscreen", options_.fullscreen.value_or(false) ? "1" : "0",
                             kCvarArchive, "1: fullscreen after vid_restart", 0.0f, 1.0f});
    host.commands().add_command(
        "vid_restart", [this](const CommandArgs&) { restart(); },
        "vid_restart: apply vid_width, vid_height and vid_fullscreen");
}

// Headless (SDL's offscreen driver) the mode stays what it opened with.
void Screen::restart() {
    if (mode_locked()) {
        return print_(
            "vid_restart: the command line's -width/-height/-window/-fullscreen keep the mode");
    }
    if (!window_.can_change_size()) {
        return print_(
            "vid_restart: this video driver cannot change the mode after start-up (use -width "
            "and -height)");
    }
    const int new_width = vid_width_->integer();
    const int new_height = vid_height_->integer();
    if (std::string why = window_.set_fullscreen(vid_fullscreen_->value() != 0); !why.empty()) {
        print_("vid_restart: " + why);
    }
    window_.set_window_size(new_width, new_height);
    if (resized_) resized_();
    print_("video mode " + std::to_string(width()) + "x" + std::to_string(height()));
}

}  // namespace nq

// The engine's screen: the window and its GL context, how every frame ends on it (the gamma
// pass, the wait while the driver has too many frames queued, the swap), the mouse and text
// input modes, and the video mode: vid_width, vid_height, vid_fullscreen and vid_restart, as
// QuakeSpasm has them (the cvars say the mode, vid_restart applies it). A size or window mode
// given on the command line (-width, -height, -window, -fullscreen) locks the mode for the
// whole run, so a config's `vid_restart` (LibreQuake's default.cfg asks for 1280x720) cannot
// override what a script or a benchmark asked for.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "common/result.h"
#include "host/host_core.h"
#include "host/launch_options.h"
#include "video/frame_throttle.h"
#include "video/gamma_pass.h"
#include "video/video_window.h"

namespace nq {

class Screen {
  public:
    using PrintFn = std::function<void(std::string_view)>;

    // Opens the window the command line asks for (640x480 windowed unless it says otherwise)
    // with its gamma pass; an error says why no window could open.
    static Result<std::unique_ptr<Screen>> open(const LaunchOptions& options, PrintFn print);
    ~Screen();
    Screen(const Screen&) = delete;
    Screen& operator=(const Screen&) = delete;

    // vid_width, vid_height, vid_fullscreen and vid_restart; `resized` runs after a new mode.
    void register_commands(HostCore& host, std::function<void()> resized);

    int width() const { return window_.drawable_width(); }
    int height() const { return window_.drawable_height(); }
    const GlInfo& gl_info() const { return window_.gl_info(); }
    // A driver's forced anti-aliasing: pixels are sampled at other points than their centres.
    bool multisampled() const { return multisampled_; }

    bool poll_event(InputEvent& event) { return window_.poll_event(event); }
    void set_text_input(bool on) { window_.set_text_input(on); }
    void set_relative_mouse(bool on);  // only a change reaches SDL

    // The frame's last passes: min(colour * contrast, 1)^gamma over the whole screen, then the
    // swap.
    void apply_levels(const ScreenLevels& levels);
    void swap();

  private:
    Screen(VideoWindow window, const LaunchOptions& options, PrintFn print);
    bool mode_locked() const;
    void restart();

    VideoWindow window_;
    FrameThrottle throttle_;
    std::optional<GammaPass> gamma_pass_;
    const LaunchOptions& options_;
    PrintFn print_;
    std::function<void()> resized_;
    Cvar* vid_width_ = nullptr;
    Cvar* vid_height_ = nullptr;
    Cvar* vid_fullscreen_ = nullptr;
    bool multisampled_ = false;
    bool relative_mouse_ = false;
};

}  // namespace nq

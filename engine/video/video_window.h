// The game window: an SDL2 window with an OpenGL core-profile context (4.5, else 3.3) whose
// functions are reached through libepoxy, plus the event pump.
//
// RAII: destroying a VideoWindow deletes the context, closes the window and releases SDL's
// video subsystem (reference-counted by SDL, so several windows may coexist). Delete GL
// objects that belong to the context before the window goes.
#pragma once

#include <SDL.h>

#include <array>
#include <memory>
#include <string>

#include "common/result.h"
#include "video/gl_info.h"
#include "video/input_event.h"
#include "video/sdl_event_translation.h"

namespace nq {

struct VideoOptions {
    int width = 640;  // window size; with fullscreen, the display mode SDL switches to
    int height = 480;
    bool fullscreen = false;
    bool vsync = false;   // off for timedemo: frames must not wait for the display
    bool hidden = false;  // no visible window (tests, offscreen rendering)
    std::string title = "NPRQuake";
};

class VideoWindow {
  public:
    // Initialises SDL video, opens the window and makes the context current. Errors (no video
    // device, no GL 3.3 core driver, bad size) come back as text, never exit the process.
    static Result<VideoWindow> create(const VideoOptions& options);

    VideoWindow(VideoWindow&&) noexcept = default;
    VideoWindow& operator=(VideoWindow&& other) noexcept;  // releases the old window in order
    ~VideoWindow() = default;

    const GlInfo& gl_info() const { return gl_info_; }
    int drawable_width() const;  // pixels; may exceed the window size on HiDPI screens
    int drawable_height() const;
    SDL_Window* sdl_window() const { return window_.get(); }

    void make_current();
    void swap();
    // Returns an empty string, or why the interval could not be set.
    std::string set_vsync(bool on);
    std::string set_fullscreen(bool on);
    void set_window_size(int width, int height);
    // False where the window cannot be resized after it opened (SDL's offscreen driver).
    bool can_change_size() const;
    // Relative mode: hidden cursor, unbounded motion (in-game mouse look).
    void set_relative_mouse(bool on);
    // Text events for the console; off in game so keys do not also type.
    void set_text_input(bool on);

    // Next pending input event, or false when there is none. Never allocates.
    bool poll_event(InputEvent& out);

    // For the plugin ABI's gl_get_proc_address (valid while a context is current).
    static void* gl_proc_address(const char* name);

  private:
    struct SdlVideoRelease {
        void operator()(int*) const;
    };
    struct WindowRelease {
        void operator()(SDL_Window* w) const { SDL_DestroyWindow(w); }
    };
    struct ContextRelease {
        void operator()(void* c) const { SDL_GL_DeleteContext(c); }
    };

    VideoWindow() = default;
    std::string open(const VideoOptions& options);

    // Declared in acquisition order so they are released in reverse.
    std::unique_ptr<int, SdlVideoRelease> sdl_video_;
    std::unique_ptr<SDL_Window, WindowRelease> window_;
    std::unique_ptr<void, ContextRelease> context_;
    GlInfo gl_info_;
    std::array<InputEvent, kMaxEventsPerSdlEvent> pending_{};
    int pending_count_ = 0, pending_next_ = 0;
};

}  // namespace nq

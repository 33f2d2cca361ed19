#include "video/video_window.h"

#include <string_view>

#include <epoxy/gl.h>

#include <utility>

#include "video/gl_context_setup.h"

namespace nq {
namespace {

// Same bound the launch options use; SDL and drivers misbehave far beyond it.
constexpr int kMaxDimension = 16384;

Error video_error(std::string message) {
    return Error{"video", 0, std::move(message)};
}

std::string check_size(const VideoOptions& options) {
    auto bad = [](int v) { return v <= 0 || v > kMaxDimension; };
    if (bad(options.width) || bad(options.height)) {
        return "window size " + std::to_string(options.width) + "x" +
               std::to_string(options.height) + " is out of range (1.." +
               std::to_string(kMaxDimension) + ")";
    }
    return {};
}

Uint32 window_flags(const VideoOptions& options) {
    Uint32 flags = SDL_WINDOW_OPENGL | SDL_WINDOW_RESIZABLE | SDL_WINDOW_ALLOW_HIGHDPI;
    if (options.fullscreen) flags |= SDL_WINDOW_FULLSCREEN;  // switches to the closest mode
    flags |= options.hidden ? SDL_WINDOW_HIDDEN : SDL_WINDOW_SHOWN;
    return flags;
}

}  // namespace

void VideoWindow::SdlVideoRelease::operator()(int*) const {
    SDL_QuitSubSystem(SDL_INIT_VIDEO);
}

VideoWindow& VideoWindow::operator=(VideoWindow&& other) noexcept {
    if (this == &other) return *this;
    context_.reset();  // a context goes before its window, the window before SDL video
    window_.reset();
    sdl_video_ = std::move(other.sdl_video_);
    window_ = std::move(other.window_);
    context_ = std::move(other.context_);
    gl_info_ = std::move(other.gl_info_);
    pending_ = other.pending_;
    pending_count_ = std::exchange(other.pending_count_, 0);
    pending_next_ = std::exchange(other.pending_next_, 0);
    return *this;
}

Result<VideoWindow> VideoWindow::create(const VideoOptions& options) {
    VideoWindow window;
    std::string error = window.open(options);
    if (!error.empty()) return video_error(std::move(error));
    return window;
}

std::string VideoWindow::open(const VideoOptions& options) {
    if (std::string error = check_size(options); !error.empty()) return error;

    if (SDL_InitSubSystem(SDL_INIT_VIDEO) != 0) {
        return std::string("cannot initialise SDL video (no video device?): ") + SDL_GetError();
    }
    static int video_token = 0;  // unique_ptr needs a non-null pointer to run its deleter
    sdl_video_.reset(&video_token);

    request_framebuffer_attributes();
    window_.reset(SDL_CreateWindow(options.title.c_str(), SDL_WINDOWPOS_CENTERED,
                                   SDL_WINDOWPOS_CENTERED, options.width, options.height,
                                   window_flags(options)));
    if (!window_) return std::string("cannot create the window: ") + SDL_GetError();

    SDL_GLContext context = nullptr;
    if (std::string error = create_core_context(window_.get(), &context); !error.empty()) {
        return error;
    }
    context_.reset(context);
    make_current();
    // Best effort: a driver that forces vsync still gives a working window.
    (void)set_vsync(options.vsync);
    gl_info_ = describe_current_context();
    return {};
}

int VideoWindow::drawable_width() const {
    int w = 0, h = 0;
    SDL_GL_GetDrawableSize(window_.get(), &w, &h);
    return w;
}

int VideoWindow::drawable_height() const {
    int w = 0, h = 0;
    SDL_GL_GetDrawableSize(window_.get(), &w, &h);
    return h;
}

void VideoWindow::make_current() {
    SDL_GL_MakeCurrent(window_.get(), context_.get());
}

void VideoWindow::swap() {
    SDL_GL_SwapWindow(window_.get());
}

std::string VideoWindow::set_vsync(bool on) {
    int result = SDL_GL_SetSwapInterval(on ? 1 : 0);
    gl_info_.swap_interval = SDL_GL_GetSwapInterval();
    if (result != 0) return std::string("cannot set the swap interval: ") + SDL_GetError();
    return {};
}

std::string VideoWindow::set_fullscreen(bool on) {
    if (SDL_SetWindowFullscreen(window_.get(), on ? SDL_WINDOW_FULLSCREEN : 0) != 0) {
        return std::string("cannot change fullscreen mode: ") + SDL_GetError();
    }
    return {};
}

bool VideoWindow::can_change_size() const {
    // The offscreen driver's surface keeps the size it was created with.
    const char* driver = SDL_GetCurrentVideoDriver();
    return !driver || std::string_view(driver) != "offscreen";
}

void VideoWindow::set_window_size(int width, int height) {
    SDL_SetWindowSize(window_.get(), width, height);
}

void VideoWindow::set_relative_mouse(bool on) {
    SDL_SetRelativeMouseMode(on ? SDL_TRUE : SDL_FALSE);
}

void VideoWindow::set_text_input(bool on) {
    if (on) {
        SDL_StartTextInput();
    } else {
        SDL_StopTextInput();
    }
}

bool VideoWindow::poll_event(InputEvent& out) {
    SDL_Event event;
    while (pending_next_ >= pending_count_) {
        if (!SDL_PollEvent(&event)) return false;
        pending_next_ = 0;
        pending_count_ = translate_sdl_event(event, pending_);
    }
    out = pending_[pending_next_++];
    if (out.type == InputEventType::Resize) {
        SDL_GL_GetDrawableSize(window_.get(), &out.width, &out.height);
    }
    return true;
}

void* VideoWindow::gl_proc_address(const char* name) {
    return SDL_GL_GetProcAddress(name);
}

}  // namespace nq

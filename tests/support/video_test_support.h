// Shared by the video_*_test.cpp files: a hidden 64x48 window on SDL's offscreen driver (Mesa
// llvmpipe through EGL, no X server needed) and a scratch directory.
#pragma once

#include "video/resident_libraries.h"

#include <dlfcn.h>
#include <gtest/gtest.h>
#include <link.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>

#include "video/video_window.h"

namespace nq::test {

inline VideoOptions offscreen_options(int width = 64, int height = 48) {
    VideoOptions options;
    options.width = width;
    options.height = height;
    options.hidden = true;
    options.vsync = false;
    options.title = "nq video test";
    return options;
}

// Fails the calling test (via ASSERT in the caller) when the window cannot be made.
inline Result<VideoWindow> make_offscreen_window(int width = 64, int height = 48) {
    setenv("SDL_VIDEODRIVER", "offscreen", 1);  // headless: no X server or Wayland needed
    auto window = VideoWindow::create(offscreen_options(width, height));
    if (window) keep_loaded_libraries_resident();
    return window;
}

}  // namespace nq::test

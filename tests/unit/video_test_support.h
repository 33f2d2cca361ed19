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

// A fresh directory under the system temp dir, removed with everything in it.
class ScratchDir {
  public:
    ScratchDir() {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        std::string name = std::string("nq_video_") + (info ? info->name() : "test") + "_" +
                           std::to_string(getpid());
        path_ = std::filesystem::temp_directory_path() / name;
        std::filesystem::remove_all(path_);
        std::filesystem::create_directories(path_);
    }
    ~ScratchDir() {
        std::error_code ec;
        std::filesystem::remove_all(path_, ec);
    }
    ScratchDir(const ScratchDir&) = delete;
    ScratchDir& operator=(const ScratchDir&) = delete;

    const std::filesystem::path& path() const { return path_; }
    std::string file(const std::string& name) const { return (path_ / name).string(); }

  private:
    std::filesystem::path path_;
};

}  // namespace nq::test

// Reading back what was rendered and saving it as a PNG; Quake-style screenshot names.
#pragma once

#include <epoxy/gl.h>

#include <string>

#include "common/result.h"
#include "video/png_io.h"

namespace nq {

// Quake's limit: nprq00.png .. nprq99.png.
inline constexpr int kMaxAutoScreenshots = 100;

// Reads `width` x `height` pixels at the origin of `framebuffer` (0 = the window's back
// buffer; otherwise its colour attachment 0) and flips them so the top row comes first.
// Restores the GL state it touches (read framebuffer binding, pack alignment).
Result<RgbImage> read_framebuffer_rgb(GLuint framebuffer, int width, int height);

// read_framebuffer_rgb + write_png. Empty string on success, otherwise why not.
std::string save_screenshot(const std::string& path, GLuint framebuffer, int width, int height);

// The first of <dir>/nprq00.png .. nprq99.png that does not exist yet, or an error when all
// are taken. The directory itself must exist.
Result<std::string> next_screenshot_path(const std::string& directory);

}  // namespace nq

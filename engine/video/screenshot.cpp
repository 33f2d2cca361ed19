#include "video/screenshot.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <system_error>

namespace nq {
namespace {

// Puts back the read framebuffer and pack alignment the caller had.
class ReadStateGuard {
  public:
    ReadStateGuard() {
        glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &framebuffer_);
        glGetIntegerv(GL_PACK_ALIGNMENT, &alignment_);
    }
    ~ReadStateGuard() {
        glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(framebuffer_));
        glPixelStorei(GL_PACK_ALIGNMENT, alignment_);
    }
    ReadStateGuard(const ReadStateGuard&) = delete;
    ReadStateGuard& operator=(const ReadStateGuard&) = delete;

  private:
    GLint framebuffer_ = 0;
    GLint alignment_ = 4;
};

// GL rows run bottom-up; images top-down.
void flip_rows(RgbImage& image) {
    size_t stride = static_cast<size_t>(image.width) * 3;
    for (int top = 0, bottom = image.height - 1; top < bottom; ++top, --bottom) {
        std::swap_ranges(image.rgb.begin() + top * stride, image.rgb.begin() + (top + 1) * stride,
                         image.rgb.begin() + bottom * stride);
    }
}

// Starts clean so a later glGetError sees only our own errors. Bounded: a lost context may
// report GL_CONTEXT_LOST on every call.
void discard_gl_errors() {
    for (int i = 0; i < 16 && glGetError() != GL_NO_ERROR; ++i) {
    }
}

std::string screenshot_name(int index) {
    char name[16];
    std::snprintf(name, sizeof name, "nprq%02d.png", index);
    return name;
}

}  // namespace

Result<RgbImage> read_framebuffer_rgb(GLuint framebuffer, int width, int height) {
    if (width <= 0 || height <= 0 || width > kMaxPngDimension || height > kMaxPngDimension) {
        return Error{
            "screenshot", 0,
            "size " + std::to_string(width) + "x" + std::to_string(height) + " is out of range"};
    }
    ReadStateGuard restore;
    discard_gl_errors();
    RgbImage image{width, height, std::vector<uint8_t>(static_cast<size_t>(width) * height * 3)};
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, image.rgb.data());
    if (GLenum error = glGetError(); error != GL_NO_ERROR) {
        char code[16];
        std::snprintf(code, sizeof code, "0x%04x", error);
        return Error{"screenshot", 0,
                     std::string("glReadPixels failed with GL error ") + code +
                         " (incomplete framebuffer or size beyond it?)"};
    }
    flip_rows(image);
    return image;
}

std::string save_screenshot(const std::string& path, GLuint framebuffer, int width, int height) {
    auto image = read_framebuffer_rgb(framebuffer, width, height);
    if (!image) return path + ": " + image.error().message;
    return write_png(path, image->width, image->height, image->rgb);
}

Result<std::string> next_screenshot_path(const std::string& directory) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (!fs::is_directory(directory, ec)) {
        return Error{directory, 0, "screenshot directory does not exist"};
    }
    for (int i = 0; i < kMaxAutoScreenshots; ++i) {
        fs::path candidate = fs::path(directory) / screenshot_name(i);
        if (!fs::exists(candidate, ec) && !ec) return candidate.string();
    }
    return Error{directory, 0, "all screenshot names nprq00.png .. nprq99.png are taken"};
}

}  // namespace nq

#include "video/png_io.h"

#include <png.h>

#include <cstring>

namespace nq {
namespace {

// png_image_free is safe on an image that was never opened or has already been freed.
struct PngImageGuard {
    png_image image;
    PngImageGuard() {
        std::memset(&image, 0, sizeof image);
        image.version = PNG_IMAGE_VERSION;
    }
    ~PngImageGuard() { png_image_free(&image); }
    PngImageGuard(const PngImageGuard&) = delete;
    PngImageGuard& operator=(const PngImageGuard&) = delete;
};

std::string size_problem(int width, int height, size_t bytes) {
    if (width <= 0 || height <= 0 || width > kMaxPngDimension || height > kMaxPngDimension) {
        return "image size " + std::to_string(width) + "x" + std::to_string(height) +
               " is out of range";
    }
    size_t expected = static_cast<size_t>(width) * static_cast<size_t>(height) * 3;
    if (bytes != expected) {
        return "pixel buffer holds " + std::to_string(bytes) + " bytes, " + std::to_string(width) +
               "x" + std::to_string(height) + " RGB needs " + std::to_string(expected);
    }
    return {};
}

}  // namespace

std::string write_png(const std::string& path, int width, int height,
                      std::span<const uint8_t> rgb) {
    if (std::string problem = size_problem(width, height, rgb.size()); !problem.empty()) {
        return path + ": " + problem;
    }
    PngImageGuard png;
    png.image.width = static_cast<png_uint_32>(width);
    png.image.height = static_cast<png_uint_32>(height);
    png.image.format = PNG_FORMAT_RGB;
    if (!png_image_write_to_file(&png.image, path.c_str(), 0, rgb.data(), width * 3, nullptr)) {
        return path + ": cannot write PNG: " + png.image.message;
    }
    return {};
}

Result<RgbImage> read_png(const std::string& path) {
    PngImageGuard png;
    if (!png_image_begin_read_from_file(&png.image, path.c_str())) {
        return Error{path, 0, std::string("cannot read PNG: ") + png.image.message};
    }
    int width = static_cast<int>(png.image.width);
    int height = static_cast<int>(png.image.height);
    if (png.image.width > kMaxPngDimension || png.image.height > kMaxPngDimension) {
        return Error{path, 0,
                     "image size " + std::to_string(png.image.width) + "x" +
                         std::to_string(png.image.height) + " is over the " +
                         std::to_string(kMaxPngDimension) + " pixel limit"};
    }
    png.image.format = PNG_FORMAT_RGB;
    RgbImage out{width, height, std::vector<uint8_t>(PNG_IMAGE_SIZE(png.image))};
    const png_color black{0, 0, 0};
    if (!png_image_finish_read(&png.image, &black, out.rgb.data(), width * 3, nullptr)) {
        return Error{path, 0, std::string("cannot decode PNG: ") + png.image.message};
    }
    return out;
}

}  // namespace nq

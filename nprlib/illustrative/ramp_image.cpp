#include "illustrative/ramp_image.h"

#include <png.h>

#include <cctype>
#include <cstring>

namespace nq::npr::illustrative {
namespace {

// png_image_free is safe on an image never opened or already freed.
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

// Empty when width x height is an acceptable ramp image size.
std::string dimension_problem(int64_t width, int64_t height) {
    const std::string size = std::to_string(width) + "x" + std::to_string(height);
    if (width < 2 || height < 1) return "bad dimensions " + size + " (a ramp needs width >= 2)";
    if (width > kMaxRampImageDimension || height > kMaxRampImageDimension ||
        width * height > kMaxRampImagePixels) {
        return "huge dimensions " + size + " (limit " + std::to_string(kMaxRampImageDimension) +
               " per side, " + std::to_string(kMaxRampImagePixels) + " pixels)";
    }
    return {};
}

int32_t read_le32(const uint8_t* p) {
    return int32_t(uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 |
                   uint32_t(p[3]) << 24);
}

bool has_lmp_extension(const std::string& file) {
    if (file.size() < 4) return false;
    std::string tail = file.substr(file.size() - 4);
    for (char& c : tail) c = char(std::tolower(static_cast<unsigned char>(c)));
    return tail == ".lmp";
}

}  // namespace

bool looks_like_png(std::span<const uint8_t> bytes) {
    static const uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    return bytes.size() >= 8 && std::memcmp(bytes.data(), kSignature, 8) == 0;
}

RampImageResult decode_png_ramp_image(std::span<const uint8_t> bytes, const std::string& file) {
    RampImageResult out;
    if (!looks_like_png(bytes)) {
        out.error = file + ": offset 0: not a PNG file (no PNG signature)";
        return out;
    }
    PngImageGuard png;
    if (!png_image_begin_read_from_memory(&png.image, bytes.data(), bytes.size())) {
        out.error = file + ": corrupt PNG header: " + png.image.message;
        return out;
    }
    if (std::string problem = dimension_problem(png.image.width, png.image.height);
        !problem.empty()) {
        out.error = file + ": offset 16: " + problem;
        return out;
    }
    png.image.format = PNG_FORMAT_RGB;
    RampImage image{int(png.image.width), int(png.image.height),
                    std::vector<uint8_t>(PNG_IMAGE_SIZE(png.image))};
    const png_color black{0, 0, 0};
    if (!png_image_finish_read(&png.image, &black, image.rgb.data(), image.width * 3, nullptr)) {
        out.error = file + ": corrupt PNG data: " + png.image.message;
        return out;
    }
    out.image = std::move(image);
    return out;
}

RampImageResult decode_lmp_ramp_image(std::span<const uint8_t> bytes, const uint8_t* palette,
                                      const std::string& file) {
    RampImageResult out;
    if (bytes.size() < 8) {
        out.error = file + ": offset " + std::to_string(bytes.size()) +
                    ": truncated .lmp header (needs 8 bytes: width, height)";
        return out;
    }
    if (!palette) {
        out.error = file + ": a .lmp ramp needs the palette, and none was given";
        return out;
    }
    const int64_t width = read_le32(bytes.data());
    const int64_t height = read_le32(bytes.data() + 4);
    if (std::string problem = dimension_problem(width, height); !problem.empty()) {
        out.error = file + ": offset 0: " + problem;
        return out;
    }
    const size_t pixels = size_t(width) * size_t(height);
    if (bytes.size() - 8 < pixels) {
        out.error = file + ": offset " + std::to_string(bytes.size()) +
                    ": truncated: " + std::to_string(width) + "x" + std::to_string(height) +
                    " needs " + std::to_string(8 + pixels) + " bytes";
        return out;
    }
    out.image.width = int(width);
    out.image.height = int(height);
    out.image.rgb.resize(pixels * 3);
    for (size_t i = 0; i < pixels; ++i) {
        std::memcpy(&out.image.rgb[i * 3], palette + size_t(bytes[8 + i]) * 3, 3);
    }
    return out;
}

WarpRampResult decode_warp_ramp(std::span<const uint8_t> bytes, const std::string& file,
                                const uint8_t* palette) {
    RampImageResult image;
    if (looks_like_png(bytes)) {
        image = decode_png_ramp_image(bytes, file);
    } else if (has_lmp_extension(file)) {
        image = decode_lmp_ramp_image(bytes, palette, file);
    } else {
        return {std::nullopt, file + ": offset 0: neither a PNG (no signature) nor a .lmp file"};
    }
    if (!image.error.empty()) return {std::nullopt, image.error};
    return ramp_from_image(image.image, file);
}

}  // namespace nq::npr::illustrative

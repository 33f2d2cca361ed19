// Fuzz target: light-warp ramp images for the illustrative style, each input decoded both as a
// PNG (libpng from memory) and as a Quake .lmp (with a fixed palette), then resampled.
// Seeds: synthetic PNGs and .lmps written here, plus (scripts/fuzz.sh) the game's .lmp pictures.
#include <png.h>

#include <cstring>

#include "fuzz_target.h"
#include "illustrative/ramp_image.h"

namespace {

std::vector<uint8_t> png_seed(int width, int height) {
    std::vector<uint8_t> rgb(size_t(width) * size_t(height) * 3);
    for (size_t i = 0; i < rgb.size(); ++i) rgb[i] = uint8_t(i * 37);
    png_image image;
    std::memset(&image, 0, sizeof image);
    image.version = PNG_IMAGE_VERSION;
    image.width = uint32_t(width);
    image.height = uint32_t(height);
    image.format = PNG_FORMAT_RGB;
    png_alloc_size_t size = 0;
    if (!png_image_write_to_memory(&image, nullptr, &size, 0, rgb.data(), 0, nullptr)) return {};
    std::vector<uint8_t> out(size);
    if (!png_image_write_to_memory(&image, out.data(), &size, 0, rgb.data(), 0, nullptr)) return {};
    out.resize(size);
    return out;
}

std::vector<uint8_t> lmp_seed(int32_t width, int32_t height) {
    std::vector<uint8_t> out(8);
    for (int i = 0; i < 4; ++i) {
        out[size_t(i)] = uint8_t(uint32_t(width) >> (8 * i));
        out[size_t(4 + i)] = uint8_t(uint32_t(height) >> (8 * i));
    }
    for (int64_t i = 0; i < int64_t(width) * height; ++i) out.push_back(uint8_t(i * 7));
    return out;
}

std::vector<nq::test::SeedFile> ramp_seeds() {
    return {{"ramp_256x1.png", png_seed(256, 1)}, {"ramp_16x4.png", png_seed(16, 4)},
            {"ramp_2x2.png", png_seed(2, 2)},     {"ramp_64x1.lmp", lmp_seed(64, 1)},
            {"ramp_8x3.lmp", lmp_seed(8, 3)},     {"ramp_1x1.lmp", lmp_seed(1, 1)}};
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
    nq::fuzz::handle_write_seeds(*argc, *argv, ramp_seeds());
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const std::vector<uint8_t> palette = [] {
        std::vector<uint8_t> p(768);
        for (size_t i = 0; i < p.size(); ++i) p[i] = uint8_t(i * 13);
        return p;
    }();
    float sum = 0.0f;
    size_t sink = 0;
    for (const char* name : {"fuzz.png", "fuzz.lmp"}) {
        const auto r = nq::npr::illustrative::decode_warp_ramp({data, size}, name, palette.data());
        sink += r.error.size();
        if (r.ramp) {
            for (const auto& c : r.ramp->rgb) sum += c.r + c.g + c.b;
        }
    }
    volatile float keep = sum + float(sink);
    (void)keep;
    return 0;
}

#include "draw2d/rgba_image.h"

#include <algorithm>

namespace nq {

RgbaImage indexed_to_rgba(int width, int height, std::span<const uint8_t> indices,
                          const Palette& palette, uint8_t transparent_index) {
    RgbaImage image;
    if (width <= 0 || height <= 0) return image;
    image.width = width;
    image.height = height;
    size_t count = static_cast<size_t>(width) * static_cast<size_t>(height);
    image.rgba.assign(count * 4, 0);
    size_t known = std::min(count, indices.size());
    for (size_t i = 0; i < known; ++i) {
        uint8_t index = indices[i];
        if (index == transparent_index) continue;
        const Rgb& colour = palette.colors[index];
        uint8_t* out = &image.rgba[i * 4];
        out[0] = colour.r;
        out[1] = colour.g;
        out[2] = colour.b;
        out[3] = 255;
    }
    return image;
}

RgbaImage pic_to_rgba(const Pic& pic, const Palette& palette) {
    return indexed_to_rgba(pic.width, pic.height, pic.pixels, palette, kTransparentIndex);
}

}  // namespace nq

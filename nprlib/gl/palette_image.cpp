#include "gl/palette_image.h"

namespace nq::npr::gl {
namespace {

bool is_transparent(uint8_t index, Transparent mode) {
    switch (mode) {
        case Transparent::index255:
            return index == kTransparentIndex;
        case Transparent::index0:
            return index == 0;
        case Transparent::none:
            break;
    }
    return false;
}

}  // namespace

void expand_palette_image(std::span<const uint8_t> pixels, const uint8_t* palette_rgb,
                          PaletteExpansion options, std::vector<uint8_t>& rgba_out) {
    rgba_out.resize(pixels.size() * 4);
    uint8_t* out = rgba_out.data();
    for (uint8_t index : pixels) {
        const uint8_t* colour = palette_rgb + index * 3;
        const bool transparent = is_transparent(index, options.transparent);
        const bool black = options.blacken_fullbrights && is_fullbright_index(index);
        out[0] = black ? 0 : colour[0];
        out[1] = black ? 0 : colour[1];
        out[2] = black ? 0 : colour[2];
        out[3] = transparent ? 0 : 255;
        out += 4;
    }
}

bool has_fullbright_pixels(std::span<const uint8_t> pixels) {
    for (uint8_t index : pixels) {
        if (is_fullbright_index(index)) return true;
    }
    return false;
}

void extract_fullbright_mask(std::span<const uint8_t> pixels, const uint8_t* palette_rgb,
                             std::vector<uint8_t>& rgba_out) {
    rgba_out.resize(pixels.size() * 4);
    uint8_t* out = rgba_out.data();
    for (uint8_t index : pixels) {
        const bool bright = is_fullbright_index(index);
        const uint8_t* colour = palette_rgb + index * 3;
        out[0] = bright ? colour[0] : 0;
        out[1] = bright ? colour[1] : 0;
        out[2] = bright ? colour[2] : 0;
        out[3] = bright ? 255 : 0;
        out += 4;
    }
}

void bleed_colour_into_transparent_texels(std::vector<uint8_t>& rgba, int width, int height) {
    auto at = [&](int x, int y) { return rgba.data() + (static_cast<size_t>(y) * width + x) * 4; };
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            uint8_t* texel = at(x, y);
            if (texel[3] != 0) continue;
            int sum[3] = {0, 0, 0};
            int count = 0;
            for (int dy = -1; dy <= 1; ++dy) {
                for (int dx = -1; dx <= 1; ++dx) {
                    // Wrap like GL_REPEAT: textures tile.
                    const int nx = (x + dx + width) % width;
                    const int ny = (y + dy + height) % height;
                    const uint8_t* n = at(nx, ny);
                    if (n[3] == 0) continue;
                    sum[0] += n[0];
                    sum[1] += n[1];
                    sum[2] += n[2];
                    ++count;
                }
            }
            for (int c = 0; c < 3; ++c) texel[c] = count ? static_cast<uint8_t>(sum[c] / count) : 0;
        }
    }
}

}  // namespace nq::npr::gl

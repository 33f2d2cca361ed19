// 8-bit Quake palette images -> RGBA8, on the CPU (no GL here, so it is testable on its own).
// Quake facts used: the palette is 256 RGB triples; indices 224..254 are the fullbright colours
// (drawn unlit); index 255 is the transparent colour of sprites and fence ("{") textures; the
// sky's front layer is transparent where the index is 0.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace nq::npr::gl {

inline constexpr int kFirstFullbrightIndex = 224;
inline constexpr int kLastFullbrightIndex = 254;
inline constexpr uint8_t kTransparentIndex = 255;

constexpr bool is_fullbright_index(uint8_t index) {
    return index >= kFirstFullbrightIndex && index <= kLastFullbrightIndex;
}

enum class Transparent {
    none,      // every pixel opaque
    index255,  // sprites, fences, alias skins: 255 -> alpha 0
    index0     // the sky's front layer: 0 -> alpha 0
};

struct PaletteExpansion {
    Transparent transparent = Transparent::none;
    // Paint fullbright pixels black: the lit base then adds nothing there and the separate
    // fullbright mask supplies the colour unlit (QuakeSpasm's "no bright" base texture).
    bool blacken_fullbrights = false;
};

// rgba_out is resized to pixels.size() * 4 (no reallocation once it has the capacity).
void expand_palette_image(std::span<const uint8_t> pixels, const uint8_t* palette_rgb,
                          PaletteExpansion options, std::vector<uint8_t>& rgba_out);

bool has_fullbright_pixels(std::span<const uint8_t> pixels);

// Fullbright pixels keep their palette colour with alpha 255; all others become (0,0,0,0), so the
// mask can simply be added on top of the lit colour.
void extract_fullbright_mask(std::span<const uint8_t> pixels, const uint8_t* palette_rgb,
                             std::vector<uint8_t>& rgba_out);

// Gives fully transparent texels the average colour of their opaque 8-neighbours (alpha stays 0),
// so linear filtering and mipmaps do not bleed a dark fringe around cut-outs.
void bleed_colour_into_transparent_texels(std::vector<uint8_t>& rgba, int width, int height);

}  // namespace nq::npr::gl

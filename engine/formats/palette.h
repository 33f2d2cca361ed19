// The 8-bit colour tables every Quake picture depends on:
//   palette.lmp  — 256 RGB triples (768 bytes).
//   colormap.lmp — 64 light levels x 256 palette indices (row 0 brightest, row 63 darkest);
//                  id's file carries one extra trailing byte, LibreQuake's does not.
// Plus the player colour translation (shirt/pants ranges) and the fullbright index range.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "common/result.h"

namespace nq {

inline constexpr int kPaletteColors = 256;
inline constexpr size_t kPaletteBytes = kPaletteColors * 3;
inline constexpr int kColormapLevels = 64;
inline constexpr size_t kColormapBytes = kColormapLevels * kPaletteColors;

// Palette indices 224..254 are drawn at full brightness regardless of light level; 255 is the
// transparent colour of sprites, skins-with-holes and HUD pictures.
inline constexpr int kFirstFullbrightIndex = 224;
inline constexpr int kLastFullbrightIndex = 254;
inline constexpr int kTransparentIndex = 255;

// Player colours: the skin pixels in [16, 32) are the shirt ("top") ramp and those in
// [96, 112) the pants ("bottom") ramp; both are replaced by the ramp of the chosen colour.
inline constexpr int kColorRampSize = 16;
inline constexpr int kShirtRangeStart = 16;
inline constexpr int kPantsRangeStart = 96;
// A player colour is a palette row 0..15 (a 4-bit field on the wire); menus offer 0..13, rows
// 14 and 15 are the fullbright ramps.
inline constexpr int kPlayerColorRows = 16;

struct Rgb {
    uint8_t r = 0, g = 0, b = 0;
    friend bool operator==(const Rgb&, const Rgb&) = default;
};

struct Palette {
    std::array<Rgb, kPaletteColors> colors{};
    std::vector<std::string> warnings;
};

struct Colormap {
    // kColormapLevels rows of kPaletteColors entries: shaded index = table[level * 256 + index].
    std::vector<uint8_t> table;
    std::vector<std::string> warnings;

    uint8_t shade(int level, uint8_t index) const {
        return table[static_cast<size_t>(level) * kPaletteColors + index];
    }
    std::span<const uint8_t> row(int level) const {
        return std::span<const uint8_t>(table).subspan(static_cast<size_t>(level) * kPaletteColors,
                                                       kPaletteColors);
    }
};

// palette.lmp: exactly 768 bytes expected; fewer is an error, extra bytes a warning.
Result<Palette> parse_palette(std::span<const uint8_t> data, const std::string& name);
// colormap.lmp: at least 64 * 256 bytes; trailing bytes are a warning.
Result<Colormap> parse_colormap(std::span<const uint8_t> data, const std::string& name);

constexpr bool is_fullbright(uint8_t index) {
    return index >= kFirstFullbrightIndex && index <= kLastFullbrightIndex;
}

// A 256-entry index remap that recolours a player skin: identity everywhere except the shirt
// and pants ranges, which take the 16-entry ramp of palette row `shirt` and `pants` (each
// clamped to 0..15). The skin ranges run dark-to-light, as do palette rows 0..7; rows 8..15
// run light-to-dark, so they are copied reversed to keep the skin's shading direction.
std::array<uint8_t, kPaletteColors> player_translation(int shirt, int pants);

}  // namespace nq

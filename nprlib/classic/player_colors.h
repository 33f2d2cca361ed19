// Quake's player colour translation: skin pixels in the shirt range (16..31) and the pants range
// (96..111) are remapped to the 16-entry palette row of the chosen colour. Colour c uses the row
// starting at c * 16; rows 8 and up run from bright to dark in the palette, so for them the ramp
// is taken in reverse to keep the skin's shading the right way round.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace nq::npr::classic {

inline constexpr int kShirtRangeStart = 16;  // "top" colour
inline constexpr int kPantsRangeStart = 96;  // "bottom" colour
inline constexpr int kColourRangeLength = 16;

using Translation = std::array<uint8_t, 256>;

// top/bottom: player colours 0..15 (higher bits ignored).
Translation player_translation(uint8_t top_colour, uint8_t bottom_colour);

void translate_pixels(std::span<const uint8_t> pixels, const Translation& translation,
                      std::vector<uint8_t>& out);

}  // namespace nq::npr::classic

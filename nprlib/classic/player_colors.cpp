#include "classic/player_colors.h"

namespace nq::npr::classic {
namespace {

void remap_range(Translation& translation, int range_start, uint8_t colour) {
    const int row = (colour & 15) * kColourRangeLength;
    const bool reversed = row >= 128;
    for (int i = 0; i < kColourRangeLength; ++i) {
        const int target = reversed ? row + kColourRangeLength - 1 - i : row + i;
        translation[static_cast<size_t>(range_start + i)] = static_cast<uint8_t>(target);
    }
}

}  // namespace

Translation player_translation(uint8_t top_colour, uint8_t bottom_colour) {
    Translation translation;
    for (int i = 0; i < 256; ++i) translation[static_cast<size_t>(i)] = static_cast<uint8_t>(i);
    remap_range(translation, kShirtRangeStart, top_colour);
    remap_range(translation, kPantsRangeStart, bottom_colour);
    return translation;
}

void translate_pixels(std::span<const uint8_t> pixels, const Translation& translation,
                      std::vector<uint8_t>& out) {
    out.resize(pixels.size());
    for (size_t i = 0; i < pixels.size(); ++i) out[i] = translation[pixels[i]];
}

}  // namespace nq::npr::classic

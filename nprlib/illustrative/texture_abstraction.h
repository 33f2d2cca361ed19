// World-texture abstraction for the illustrative style: the TF2 look paints environments with
// little high-frequency detail and strong, saturated colour, so each (palette-decoded, tiling)
// world texture is run once at load time through
//   1. a Kuwahara filter (kuwahara_filter.h): flattens noise and speckle, keeps edges;
//   2. a saturation boost around each pixel's luma (greys stay grey);
//   3. a value-contrast boost around the texture's mean luma, so the texture's overall
//      brightness (which the lightmaps were made for) stays where it was.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace nq::npr::illustrative {

struct AbstractionSettings {
    int radius = 2;            // Kuwahara quadrant radius in texels; 0 turns the filter off
    float saturation = 1.35f;  // 1 = unchanged, 0 = grey
    float contrast = 1.15f;    // 1 = unchanged; scales luma's distance from the mean luma
};

// In place on RGB8 (size a multiple of 3). Colours are clamped to 0..255.
void boost_saturation_and_contrast(std::vector<uint8_t>& rgb, float saturation, float contrast);

// RGB8 width x height in, RGB8 of the same size out (empty when the sizes do not match).
std::vector<uint8_t> abstract_texture(std::span<const uint8_t> rgb, int width, int height,
                                      const AbstractionSettings& settings = {});

// The same on RGBA8 (e.g. gl::expand_palette_image's output): alpha is kept as it is.
std::vector<uint8_t> abstract_texture_rgba(std::span<const uint8_t> rgba, int width, int height,
                                           const AbstractionSettings& settings = {});

}  // namespace nq::npr::illustrative

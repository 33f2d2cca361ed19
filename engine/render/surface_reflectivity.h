// How much of the light arriving at a world surface it sends back, per texture: the average
// colour of the texture's pixels, decoded through the game palette (Source's light compiler
// takes a texture's reflectivity the same way, from its average colour).
//
// Each channel is the mean of the palette bytes of the pixels of mip level 0, divided by 255
// (the palette's own, gamma-encoded values: Quake draws them as they are at light level 128).
// Fence textures ('{' names) leave out their transparent index 255. A texture without pixels,
// or any texture when no palette is given, reflects kDefaultReflectivity in every channel.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "formats/bsp.h"

namespace nq {

inline constexpr float kDefaultReflectivity = 0.5f;

using PaletteBytes = std::array<uint8_t, 768>;

// One RGB reflectivity (0..1) per texture of `bsp`, parallel to Bsp::textures.
std::vector<glm::vec3> texture_reflectivity(const Bsp& bsp,
                                            const std::optional<PaletteBytes>& palette);

}  // namespace nq

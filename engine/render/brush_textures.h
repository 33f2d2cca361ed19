// The textures of a brush model as nqr_texture records: pixels, flags (sky, liquid, missing)
// and animation chains.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "formats/bsp.h"
#include "nqr_renderer.h"

namespace nq {

// NQR_TEXTURE_SKY for names starting "sky" (any case), NQR_TEXTURE_LIQUID for names starting
// '*' (water, slime, lava, teleporters); 0 otherwise.
uint32_t texture_flags_for_name(std::string_view name);

struct BrushTextures {
    std::vector<nqr_texture> textures;  // parallel to Bsp::textures
    std::vector<std::string> warnings;
};

// The records point at the names and pixels of `bsp.textures`, which must outlive them.
BrushTextures build_brush_textures(const Bsp& bsp);

}  // namespace nq

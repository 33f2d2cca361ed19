// RGB lightmap samples for a brush model: the map's .lit file when it matches the map, else the
// grey lighting lump with every sample repeated three times.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "formats/bsp.h"

namespace nq {

struct LightingRgb {
    std::vector<uint8_t> rgb;  // 3 bytes per sample of Bsp::lighting; empty when the map has none
    bool from_lit = false;
    std::vector<std::string> warnings;
};

// `lit_file` is the .lit's bytes, empty when there is none. A .lit that fails to parse or does
// not match the map is ignored with a warning.
LightingRgb build_lighting_rgb(const Bsp& bsp, std::span<const uint8_t> lit_file,
                               const std::string& lit_name);

// The .lit file that goes with a map: "maps/e1m1.bsp" -> "maps/e1m1.lit".
std::string lit_name_for(const std::string& map_name);

}  // namespace nq

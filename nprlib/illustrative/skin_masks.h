// Specular and rim masks for Quake skins, which have none: the TF2 shading needs per texel
// k_s (specular mask), k_spec (specular exponent) and k_r (rim mask). They are derived from the
// palette index of each skin texel, as a 256-entry table made once per palette.
//
// The rule (Quake's palette is 16 rows of 16 colours, each row one ramp from light to dark or
// back; rows named by their first index):
//   - Metal rows: 0 (neutral greys: steel, chrome), 32 (blue-greys: gun metal), 80 (brass and
//     bronze browns-to-gold), 192 (yellows: gold). Their texels are metal on Quake's models, so
//     k_s = 0.35 + 0.65 * V (V = max(r, g, b) / 255) and exponent = 20 + 130 * V: bright metal is
//     a tight, strong highlight, dark metal a weak broad one.
//   - Everything else (leather, cloth, flesh, wood, blood) is dielectric: k_s follows how
//     bright and unsaturated the colour is, k_s = 0.05 + 0.45 * (V * (1 - S))^1.5 (S = HSV
//     saturation), and exponent = 4 + 26 * V * (1 - S): dark saturated cloth and skin stay
//     nearly matte, pale surfaces get a soft sheen.
//   - Fullbright indices (224..254) glow and get no highlight: k_s = 0, exponent 1.
//   - k_r (rim) is 1 except for very dark texels, which fade it toward 0.3
//     (k_r = 0.3 + 0.7 * smoothstep(0, 0.15, luma)): a crisp rim on a black hole or a
//     shadowed crevice painted into the skin would look like a halo.
//   - Index 255 (transparent on holey models) gets k_s = 0, k_r = 0.
// Only indices are used, so the masks are the same for any player-colour translation.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace nq::npr::illustrative {

// The exponent range the G channel spans: G = (exponent - min) / (max - min).
inline constexpr float kMinSpecularExponent = 1.0f;
inline constexpr float kMaxSpecularExponent = 150.0f;

struct TexelMasks {
    float specular = 0.0f;  // k_s, 0..1
    float exponent = 1.0f;  // k_spec, kMinSpecularExponent..kMaxSpecularExponent
    float rim = 1.0f;       // k_r, 0..1
};

using PaletteMasks = std::array<TexelMasks, 256>;

// The palette rows (first index) the rule treats as metal.
bool is_metal_palette_index(uint8_t index);

// `palette`: 256 RGB triples (768 bytes).
PaletteMasks derive_palette_masks(const uint8_t* palette);

// G channel value for an exponent and back.
float encode_specular_exponent(float exponent);
float decode_specular_exponent(float encoded);

// RGBA8, width x height, in the skin's texel order: R = k_s, G = encoded exponent, B = k_r,
// A = 255. `pixels` holds width * height palette indices.
std::vector<uint8_t> derive_skin_masks(std::span<const uint8_t> pixels, int width, int height,
                                       const PaletteMasks& masks);

}  // namespace nq::npr::illustrative

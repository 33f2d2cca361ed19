// Per-model material files for the illustrative style, e.g. `progs/ogre.mdl.mat`: a few of
// Source's VertexLitGeneric keys (VMT-like syntax) that override the style's defaults for one
// model. Untrusted input.
//
// Syntax: one `key value` per line; key and value optionally in double quotes; `//` starts a
// comment (outside quotes); blank lines are fine; a surrounding `"VertexLitGeneric" { ... }`
// (any shader name) is tolerated. Keys are case-insensitive:
//   $phongexponent      float      specular exponent                     clamped to [1, 1000]
//   $phongboost         float      specular multiplier                   clamped to [0, 100]
//   $phongfresnelranges "[a b c]"  Fresnel remap at 0, 0.5, 1            each clamped to [0, 10]
//   $rimlight           0/1        rim lighting on/off
//   $rimlightexponent   float                                             clamped to [0.1, 100]
//   $rimlightboost      float                                             clamped to [0, 100]
//   $rimmask            0/1        use the derived rim mask (skin_masks.h)
//   $lightwarptexture   string     ramp name ("tf2", "neutral", "cel") or a path
//   $selfillum          0/1        fullbright texels glow
//   $ambientscale       float      multiplier on the ambient cube term    clamped to [0, 10]
// Soft problems (unknown key, bad number, value clamped, missing value, repeated key) are
// warnings with their line number and the rest of the file still counts. Hard problems
// (binary data, a line over kMaxMaterialLineLength, a file over kMaxMaterialFileSize) make the
// whole file an error: the caller then uses the defaults.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace nq::npr::illustrative {

inline constexpr size_t kMaxMaterialFileSize = 64 * 1024;
inline constexpr size_t kMaxMaterialLineLength = 1024;

// Only what the file set: an empty field means "keep the style's default".
struct MaterialOverrides {
    std::optional<float> phong_exponent;
    std::optional<float> phong_boost;
    std::optional<std::array<float, 3>> phong_fresnel_ranges;
    std::optional<bool> rim_light;
    std::optional<float> rim_light_exponent;
    std::optional<float> rim_light_boost;
    std::optional<bool> rim_mask;
    std::optional<std::string> light_warp_texture;
    std::optional<bool> self_illum;
    std::optional<float> ambient_scale;
};

struct MaterialWarning {
    int line = 0;  // 1-based
    std::string message;
};

struct MaterialParseResult {
    MaterialOverrides material;
    std::vector<MaterialWarning> warnings;
    std::string error;   // empty on success; otherwise "FILE:LINE: problem", material is empty
    int error_line = 0;  // 1-based line of the error (0: the whole file, e.g. its size)

    bool ok() const { return error.empty(); }
};

MaterialParseResult parse_material_file(std::span<const uint8_t> bytes, const std::string& file);

// "progs/ogre.mdl.mat:3: unknown key $foo" for logs.
std::string format_material_warning(const std::string& file, const MaterialWarning& warning);

}  // namespace nq::npr::illustrative

// The 1D "light warp" ramp w() of Valve's "Illustrative Rendering in Team Fortress 2" (Mitchell,
// Francke, Eng, NPAR 2007): the diffuse term is w(half_lambert(n, l)), where the ramp recolours
// shading so that shadows turn cool instead of black and the terminator gets a warm band.
//
// A ramp is 256 RGB entries in 0..1 indexed by the half-Lambert value 0..1 (0: facing away from
// the light, 1: facing it). The shader reads it times 2 (up to 2x overbright), so 0.5 is the
// neutral mid-grey and "neutral" (i/255 * 0.5) gives back plain half-Lambert shading.
//
// Built-in ramps are generated here (no image files to ship): "tf2", "neutral", "cel".
// User ramps (PNG or Quake .lmp) are decoded by ramp_image.h and resampled by ramp_from_image.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

namespace nq::npr::illustrative {

inline constexpr int kWarpRampSize = 256;

struct WarpRamp {
    std::array<glm::vec3, kWarpRampSize> rgb{};  // 0..1, read x2 by the shader

    // RGB8 texels (256 x 1) for a GL upload.
    std::vector<uint8_t> to_rgb8() const;
};

// Either a ramp or an error naming the file and the problem (`ramp` is then empty).
struct WarpRampResult {
    std::optional<WarpRamp> ramp;
    std::string error;
};

// The paper's three regions: a cool blue-grey gradient in shadow (never black), a narrow reddish
// band at the terminator (x ~ 0.5), a grey gradient rising to just above mid-grey on the lit side.
WarpRamp tf2_warp_ramp();
// Plain half-Lambert: entry i is grey i/255 * 0.5.
WarpRamp neutral_warp_ramp();
// Three hard grey bands (shadow, mid, lit) for a cel-shaded look.
WarpRamp cel_warp_ramp();

// "tf2", "neutral" or "cel" (case-insensitive); nullopt for anything else.
std::optional<WarpRamp> builtin_warp_ramp(std::string_view name);

// An RGB8 image, rows top to bottom.
struct RampImage {
    int width = 0, height = 0;
    std::vector<uint8_t> rgb;  // width * height * 3
};

// Resamples the middle row of `image` to 256 entries (linear, texel centres aligned with the
// ramp's first and last entries). Needs width >= 2 and height >= 1; `file` names it in errors.
WarpRampResult ramp_from_image(const RampImage& image, const std::string& file);

// Reads a file's bytes (e.g. through the engine's virtual filesystem); nullopt if missing.
using RampFileReader = std::function<std::optional<std::vector<uint8_t>>(const std::string&)>;

// A built-in name, or else a path read with `read_file` and decoded as PNG (by its signature)
// or Quake .lmp (by its extension; needs `palette`, 768 bytes, may be null for PNG only).
WarpRampResult find_warp_ramp(std::string_view name_or_path, const RampFileReader& read_file,
                              const uint8_t* palette);

}  // namespace nq::npr::illustrative

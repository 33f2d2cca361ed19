// Builds one surface's lightmap on the CPU, as GLQuake/QuakeSpasm do each time a surface's light
// changes: the sum over its (up to 4) light styles of sample x style value, plus dynamic lights,
// stored as bytes with QuakeSpasm's overbright convention (gl_overbright 1, its default):
//     stored = min(255, sum)      and the shader draws    texture x stored / 255 x 2
// so a sample of 128 at normal style ('m') shows the texture at about its own colour and brighter
// samples reach up to twice that. (GLQuake without overbright stored min(255, 2 x sum), i.e. the
// same scale clipped at 1.) Maps without light data are fully lit (255); a surface without
// samples is black apart from dynamic lights.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

#include "nqr_renderer.h"

namespace nq::npr::classic {

inline constexpr int kMaxLightStyles = 4;
inline constexpr int kNumFrameLightStyles = 64;  // nqr_frame::lightstyles entries
inline constexpr uint8_t kUnusedStyle = 255;

// Quake's style value for 'm' (normal) is 12 * 22 = 264 in 8.8 fixed point, slightly above 1;
// the ABI gives 'm' as 1.0, so this restores Quake's exact brightness.
inline constexpr float kQuakeStyleUnit = 264.0f / 256.0f;

struct SurfaceLightmapSize {
    int width = 0, height = 0;  // samples; 0 when the surface has no lightmap extents
    int samples() const { return width * height; }
};

SurfaceLightmapSize surface_lightmap_size(const nqr_surface& surface);

int count_styles(const nqr_surface& surface);

// The frame's value for a style: 1.0 = normal; styles past the table are normal (Quake's table
// of 256 values holds 'm' there).
float frame_style_value(const float* lightstyles, uint8_t style);

// Whether the surface carries valid samples for all its styles in `lighting`.
bool surface_has_samples(const nqr_surface& surface, size_t num_light_samples);

struct DynamicLight {
    float origin[3];  // in the surface's model space
    float radius;
    float colour[3];  // 1 = white at Quake's strength
};

// True when the light's sphere reaches the surface's lightmap rectangle (GLQuake marks these).
bool dynamic_light_reaches(const nqr_surface& surface, const DynamicLight& light);

struct SurfaceLightInput {
    const nqr_surface* surface = nullptr;
    const uint8_t* lighting_rgb = nullptr;  // the brush model's; nullptr: map has no light data
    size_t num_light_samples = 0;
    float style_values[kMaxLightStyles] = {};  // frame_style_value() of each used style
    std::span<const DynamicLight> dynamic_lights;
};

// Writes width x height RGBA texels at `dest` (rows `dest_row_bytes` apart). `accumulator` must
// hold 3 x samples floats.
void build_surface_lightmap(const SurfaceLightInput& input, float* accumulator, uint8_t* dest,
                            size_t dest_row_bytes);

}  // namespace nq::npr::classic

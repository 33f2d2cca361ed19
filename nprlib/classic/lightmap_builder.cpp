#include "classic/lightmap_builder.h"

#include <algorithm>
#include <cmath>

namespace nq::npr::classic {
namespace {

float dot3(const float* a, const float* b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

void add_static_styles(const SurfaceLightInput& input, int samples, float* accumulator) {
    const nqr_surface& surface = *input.surface;
    const uint8_t* source = input.lighting_rgb + static_cast<size_t>(surface.light_offset) * 3;
    const int styles = count_styles(surface);
    for (int style = 0; style < styles; ++style) {
        const float scale = input.style_values[style] * kQuakeStyleUnit;
        for (int i = 0; i < samples * 3; ++i) accumulator[i] += source[i] * scale;
        source += static_cast<size_t>(samples) * 3;
    }
}

// GLQuake's falloff: distance in the lightmap plane measured as max + min / 2 of the two axis
// distances (in texels), light = radius left after the plane distance, minus that distance.
void add_dynamic_light(const nqr_surface& surface, const DynamicLight& light,
                       SurfaceLightmapSize size, float* accumulator) {
    const float plane_distance = dot3(light.origin, surface.normal) - surface.dist;
    const float reach = light.radius - std::fabs(plane_distance);
    if (reach <= 0.0f) return;
    float impact[3];
    for (int i = 0; i < 3; ++i) impact[i] = light.origin[i] - surface.normal[i] * plane_distance;
    const float local_s = dot3(impact, surface.tex_s) + surface.tex_s[3] - surface.texture_mins[0];
    const float local_t = dot3(impact, surface.tex_t) + surface.tex_t[3] - surface.texture_mins[1];
    for (int t = 0; t < size.height; ++t) {
        const float dt = std::fabs(local_t - static_cast<float>(t * 16));
        for (int s = 0; s < size.width; ++s) {
            const float ds = std::fabs(local_s - static_cast<float>(s * 16));
            const float distance = ds > dt ? ds + dt * 0.5f : dt + ds * 0.5f;
            if (distance >= reach) continue;
            float* texel = accumulator + (static_cast<size_t>(t) * size.width + s) * 3;
            for (int c = 0; c < 3; ++c) texel[c] += (reach - distance) * light.colour[c];
        }
    }
}

}  // namespace

SurfaceLightmapSize surface_lightmap_size(const nqr_surface& surface) {
    if (surface.extents[0] < 0 || surface.extents[1] < 0) return {};
    return {(surface.extents[0] >> 4) + 1, (surface.extents[1] >> 4) + 1};
}

int count_styles(const nqr_surface& surface) {
    int styles = 0;
    while (styles < kMaxLightStyles && surface.styles[styles] != kUnusedStyle) ++styles;
    return styles;
}

float frame_style_value(const float* lightstyles, uint8_t style) {
    if (lightstyles == nullptr || style >= kNumFrameLightStyles) return 1.0f;
    return lightstyles[style];
}

bool surface_has_samples(const nqr_surface& surface, size_t num_light_samples) {
    if (surface.light_offset < 0) return false;
    const size_t per_style = static_cast<size_t>(surface_lightmap_size(surface).samples());
    const size_t needed = static_cast<size_t>(count_styles(surface)) * per_style;
    const size_t offset = static_cast<size_t>(surface.light_offset);
    return offset <= num_light_samples && needed <= num_light_samples - offset;
}

bool dynamic_light_reaches(const nqr_surface& surface, const DynamicLight& light) {
    const float plane_distance = dot3(light.origin, surface.normal) - surface.dist;
    const float reach = light.radius - std::fabs(plane_distance);
    if (reach <= 0.0f) return false;
    float impact[3];
    for (int i = 0; i < 3; ++i) impact[i] = light.origin[i] - surface.normal[i] * plane_distance;
    const float local_s = dot3(impact, surface.tex_s) + surface.tex_s[3] - surface.texture_mins[0];
    const float local_t = dot3(impact, surface.tex_t) + surface.tex_t[3] - surface.texture_mins[1];
    return local_s > -reach && local_s < surface.extents[0] + reach && local_t > -reach &&
           local_t < surface.extents[1] + reach;
}

void build_surface_lightmap(const SurfaceLightInput& input, float* accumulator, uint8_t* dest,
                            size_t dest_row_bytes) {
    const nqr_surface& surface = *input.surface;
    const SurfaceLightmapSize size = surface_lightmap_size(surface);
    const int samples = size.samples();
    if (input.lighting_rgb == nullptr) {
        std::fill(accumulator, accumulator + samples * 3, 255.0f);  // unlit map: full light
    } else {
        std::fill(accumulator, accumulator + samples * 3, 0.0f);
        if (surface_has_samples(surface, input.num_light_samples)) {
            add_static_styles(input, samples, accumulator);
        }
    }
    for (const DynamicLight& light : input.dynamic_lights) {
        add_dynamic_light(surface, light, size, accumulator);
    }
    for (int t = 0; t < size.height; ++t) {
        uint8_t* row = dest + static_cast<size_t>(t) * dest_row_bytes;
        const float* light = accumulator + static_cast<size_t>(t) * size.width * 3;
        for (int s = 0; s < size.width; ++s) {
            for (int c = 0; c < 3; ++c) {
                row[s * 4 + c] = static_cast<uint8_t>(std::clamp(light[s * 3 + c], 0.0f, 255.0f));
            }
            row[s * 4 + 3] = 255;
        }
    }
}

}  // namespace nq::npr::classic

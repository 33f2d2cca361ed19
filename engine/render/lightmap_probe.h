// Finding the lit surface a ray meets and reading its lightmap there: the core of Quake's
// R_LightPoint, generalised to any ray.
//
// The ray walks the world's node tree front to back. Where it crosses a node's plane, the faces
// stored on that node are tested: the first one whose lightmap rectangle (texture_mins ..
// texture_mins + extents in texel space) holds the crossing point is the hit. Sky and liquid
// faces have no lightmap and are passed through (sky can stop the ray instead, see below).
#pragma once

#include <cstdint>
#include <optional>
#include <span>

#include <glm/glm.hpp>

#include "formats/bsp.h"

namespace nq {

struct SurfaceHit {
    uint32_t face = 0;
    glm::vec3 point{0.0f};
    // Texel coordinates relative to the face's texture_mins: 0..extents.
    float s = 0.0f;
    float t = 0.0f;
    bool sky = false;  // stopped at a sky face (only with stop_at_sky)
};

// The first lightmapped face along start -> end, or nothing. With stop_at_sky, a sky face ends
// the search (the ray left the map through the sky) and is returned with sky = true.
std::optional<SurfaceHit> first_surface_along(const Bsp& bsp, const glm::vec3& start,
                                              const glm::vec3& end, bool stop_at_sky = false);

// Light at a hit in Quake light units (lightmap bytes: 0..255 per style), every style scaled by
// lightstyles[style] (1 = normal, style numbers beyond the span count as 1). Bilinear between
// the four nearest samples (Quake took the sample below-left; bilinear keeps a moving entity's
// light from stepping every 16 texels). `rgb` is the RGB lighting (3 bytes per sample).
// A face without samples gives 0.
glm::vec3 sample_lightmap(const Bsp& bsp, std::span<const uint8_t> rgb, const SurfaceHit& hit,
                          std::span<const float> lightstyles);

}  // namespace nq

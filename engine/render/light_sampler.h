// Lighting for entities (nqr_entity_light), sampled from the map at the entity's origin.
//
// LEVEL. Quake's R_LightPoint: a ray from the origin straight down 2048 units to the first
// lit surface (lightmap_probe.h), whose lightmap gives L in Quake light units (lightmap bytes,
// every style scaled by its lightstyle value, bilinear). A map without lighting gives 255,
// a ray that hits nothing 0. Dynamic lights add (radius - distance) where positive, the
// query's minimum_level is applied (GLQuake: 24 for the view model, "always give the gun some
// light"; 8 for players), then Quake's split into an ambient and a directional part:
//     ambientlight = min(L, 128)
//     shadelight   = min(L, 192 - ambientlight)
//     nqr_entity_light.ambient     = ambientlight / 128
//     nqr_entity_light.directional = shadelight / 128
// so 1 = a lightmap value of 128 (the texture's own colours: software Quake's colormap row 32,
// GL's 2x overbright), and a model is lit ambient + directional * max(0, dot(n, direction)),
// at most 1.5 - software Quake's alias lighting. GLQuake drew with its shadelight alone,
// scaled by a yaw-dependent shadedots table: its shadelight / 200 = directional * 0.64.
//
// DIRECTION. dominant_light_direction (light_direction.h): the light entities weighted by
// brightness / distance^2 with soft line-of-sight, blended with a faint light from above.
//
// COLOUR. The RGB (.lit) sample under the point divided by its largest channel (1, 1, 1 for
// white light and for grey maps).
//
// AMBIENT CUBE. The map's baked ambient cube field at the point (ambient_cube_field.h: the
// light the surroundings send toward it, sampled at level load, blended between nearby
// samples), or, without a field or without a sample near the point, the point's own RGB level
// on every face. Dynamic lights add (radius - distance) * max(0, dot(axis, toward the light))
// in their colour (scaled to a strongest channel of 1; they also tint `color`). Divided by 128
// like the level.
//
// LIGHTS (ABI 1.4). The strongest local lights at the point (entity_lights.h), as they are;
// the engine fades them in and out per entity (light_list_smoother.h).
// Deterministic; the cube is continuous except where a sample goes out of sight
// (LightSmoother).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "formats/bsp.h"
#include "nqr_renderer.h"
#include "render/ambient_cube_field.h"
#include "render/entity_lights.h"
#include "render/light_direction.h"
#include "render/light_entities.h"

namespace nq {

inline constexpr float kLightPointDepth = 2048.0f;
inline constexpr float kViewModelMinimumLight = 24.0f;
inline constexpr float kPlayerMinimumLight = 8.0f;

struct EntityLightQuery {
    glm::vec3 origin{0.0f};
    float minimum_level = 0.0f;  // Quake light units (kViewModelMinimumLight, ...)
    bool fullbright = false;     // ambient 1, no direction, white cube
};

class LightSampler {
  public:
    // Keeps references to `bsp`, `lighting_rgb` (3 bytes per lightmap sample, empty for an
    // unlit map; BrushModelData::lighting_rgb()) and `field` (may be null), which must outlive
    // the sampler.
    LightSampler(const Bsp& bsp, std::span<const uint8_t> lighting_rgb,
                 std::vector<LightEntity> lights, const AmbientCubeField* field = nullptr);

    // Quake's R_LightPoint in RGB: light arriving at the ground under `point`.
    glm::vec3 light_point(const glm::vec3& point, std::span<const float> lightstyles) const;

    // Fills `out` (size included). `lightstyles`: 64 values, 1 = normal. `lights`, when given,
    // receives the strongest lights with their identities (for LightListSmoother).
    // Allocation-free.
    void sample(const EntityLightQuery& query, std::span<const float> lightstyles,
                DlightList dlights, EntityLighting& out,
                LightContributions* lights = nullptr) const;

    const std::vector<LightEntity>& lights() const { return lights_; }

  private:
    AmbientCube ambient_cube(const glm::vec3& point, const glm::vec3& fallback) const;

    const Bsp& bsp_;
    std::span<const uint8_t> rgb_;
    std::vector<LightEntity> lights_;
    const AmbientCubeField* field_;
};

}  // namespace nq

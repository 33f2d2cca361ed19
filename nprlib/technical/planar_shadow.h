// Planar projected shadows ("Technical Quake", after Blinn's "Me and my (fake) shadow"): the
// floor under an entity is found with the engine's trace, and the model is flattened onto that
// plane along the light direction. With penumbra on, three projections approximate a soft edge:
// an umbra scaled down about the shadow's centre, and two unscaled copies shifted sideways.
// Pure math (no GL): the matrices are drawn by ShadowDrawer.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "nqr_renderer.h"
#include "technical/technical_settings.h"

namespace nq::npr::technical {

// The plane dot(normal, x) = distance that an entity's shadow falls on, and where the trace hit it.
struct ShadowPlane {
    bool found = false;
    glm::vec3 normal{0, 0, 1};
    float distance = 0;
    glm::vec3 hit{0};
};

// Where an entity's shadow falls: traces straight down from `origin` (engine->trace, world hull)
// at most max_drop units; found = false when nothing is hit, the start is in solid, or the
// engine has no trace.
ShadowPlane find_shadow_plane(const nqr_engine& engine, const glm::vec3& origin, float max_drop);

struct ShadowPass {
    glm::mat4 world_to_plane{1.0f};
    float alpha = 0;
};

struct ShadowPasses {
    int count = 0;
    ShadowPass pass[3];
    glm::vec3 light{0, 0, 1};  // unit, toward the light: the direction the passes project along
    // A sphere on the plane holding every projection of a caster of radius caster_radius:
    // whether the shadow can be on screen when the caster is not.
    glm::vec3 bounds_centre{0};
    float bounds_radius = 0;
};

// Lights closer to the plane than this are raised to it, so shadows stay finite.
inline constexpr float kMinShadowLightElevationDegrees = 15.0f;

// The projections to draw for one entity: none when shadows are off, no plane was found or the
// light (light_dir: toward the light, world space) is at or below the plane; one hard shadow at
// settings.alpha when penumbra is off; otherwise the umbra (scaled by umbra_scale about the
// projection of `centre`, at settings.alpha) and two penumbra projections shifted
// +-penumbra_offset perpendicular to the light's direction along the plane, at penumbra_alpha.
// Each world_to_plane maps world space onto the plane along the (steepened) light direction.
// caster_radius bounds the caster about `centre` (for ShadowPasses' bounds only).
ShadowPasses build_shadow_passes(const ShadowPlane& plane, const glm::vec3& light_dir,
                                 const glm::vec3& centre, const ShadowSettings& settings,
                                 float caster_radius = 0.0f);

// The parallel projection onto the plane dot(n, x) = d along unit direction l (dot(n, l) > 0).
glm::mat4 planar_projection(const glm::vec3& n, float d, const glm::vec3& l);

// light_dir raised toward the plane normal n so that it makes at least min_elevation_degrees
// with the plane (unchanged when it already does). Both unit vectors, dot(n, light_dir) > 0.
glm::vec3 steepen_light(const glm::vec3& n, const glm::vec3& light_dir,
                        float min_elevation_degrees);

}  // namespace nq::npr::technical

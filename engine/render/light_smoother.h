// Per-entity smoothing of sampled lighting over time, so an entity's light never snaps: the
// direction turns toward each new sample along the great circle, and every level (ambient,
// directional, colour, ambient cube) follows an exponential moving average, both with time
// constant kLightSmoothingSeconds:
//     t = 1 - exp(-dt / kLightSmoothingSeconds)
//     direction = slerp(previous, sampled, t);  level = mix(previous, sampled, t)
// In one update the direction turns by at most angle * t <= pi * dt / kLightSmoothingSeconds.
// The light list (num_lights, lights) passes through as sampled: LightListSmoother
// (light_list_smoother.h) fades it.
// The engine keeps one smoother per entity (by entity number) and resets it when the entity
// appears, changes model or teleports.
#pragma once

#include <glm/glm.hpp>

#include "nqr_renderer.h"
#include "render/entity_lighting.h"

namespace nq {

inline constexpr float kLightSmoothingSeconds = 0.1f;

class LightSmoother {
  public:
    // Blends `sampled` into the state and writes the result to `out` (which may be `sampled`).
    // The first update after construction or reset() takes `sampled` as it is; dt <= 0 keeps
    // the previous result.
    void update(const EntityLighting& sampled, float dt, EntityLighting& out);
    void reset() { valid_ = false; }
    bool valid() const { return valid_; }

  private:
    EntityLighting state_{};
    bool valid_ = false;
};

// The unit vector `t` of the way from unit vector `from` to unit vector `to` along the great
// circle (any perpendicular way when they are opposite).
glm::vec3 slerp_unit(const glm::vec3& from, const glm::vec3& to, float t);

}  // namespace nq

// Per-entity smoothing of the strongest-lights list (entity_lights.h) over time, so no light
// pops as it enters or leaves an entity's set (nqr_entity_light.lights).
//
// The smoother tracks up to kTrackedLights lights by identity: light entities by index,
// dynamic lights (whose indices change from frame to frame) by position, the same light when
// within kDynamicLightMatch units of where it was. Each tracked light has a fade weight:
// while it is in the sampled set the weight rises toward 1, once out of it falls toward 0, by
// dt / kLightFadeSeconds per update (then it is forgotten). Its colour follows the sampled one
// with LightSmoother's exponential average (kLightSmoothingSeconds), and holds while it fades
// out. The output is the kMaxEntityLights tracked lights with the largest faded strength,
// strongest first, colour * smoothstep(weight).
//
// The first update after construction or reset() takes the sampled set at full weight, as
// LightSmoother takes its first sample. dt <= 0 holds the previous result. Allocation-free.
#pragma once

#include <array>
#include <cstdint>

#include <glm/glm.hpp>

#include "nqr_renderer.h"
#include "render/entity_lights.h"

namespace nq {

inline constexpr float kLightFadeSeconds = 0.15f;
inline constexpr int kTrackedLights = 2 * kMaxEntityLights;
inline constexpr float kDynamicLightMatch = 64.0f;

class LightListSmoother {
  public:
    // Blends `sampled` into the state and writes the result to out.num_lights / out.lights.
    void update(const LightContributions& sampled, float dt, EntityLighting& out);
    void reset() { valid_ = false; }

  private:
    struct Tracked {
        LightContribution light;  // the latest (smoothed) colour and position
        float weight = 0.0f;      // 0..1, linear in time
        bool in_set = false;      // in this update's sampled set
        bool used = false;
    };
    Tracked* find(const LightContribution& light);
    Tracked* free_slot();
    void advance(const LightContributions& sampled, float dt);
    void write(EntityLighting& out) const;

    std::array<Tracked, kTrackedLights> tracked_{};
    bool valid_ = false;
};

}  // namespace nq

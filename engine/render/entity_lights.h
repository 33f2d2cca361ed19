// The few local lights that matter most at a point: the map's light entities and the frame's
// dynamic lights, each with the light it brings there (nqr_entity_light.lights).
//
// A light entity brings its value at the distance as the light tools compute it (light_level):
// linear lights (delay 0) brightness - distance * wait, zero beyond; the far-reaching falloffs
// by their formulas, never above the brightness. Scaled by its style's current value
// (lightstyles), by the soft line of sight of light_direction.h (light_visibility: the fraction
// of five probe points around the light the point sees), and coloured by its "_color".
// A dynamic light brings radius - distance where positive, in its colour scaled to a strongest
// channel of 1 (as LightSampler adds it); Quake tests no line of sight for them, nor does this.
// Colours are in the ambient's scale: light units / 128.
//
// The kMaxEntityLights strongest (by mean of the RGB channels) are kept, strongest first. To
// bound the traces, only the kMaxLightCandidates strongest light entities before the line-of-
// sight test are tested, strongest first, and none once the list holds kMaxEntityLights
// lights at least as strong as the next one unoccluded. Allocation-free.
#pragma once

#include <array>
#include <cstdint>
#include <span>

#include <glm/glm.hpp>

#include "formats/bsp.h"
#include "nqr_renderer.h"
#include "render/entity_lighting.h"
#include "render/light_direction.h"
#include "render/light_entities.h"

namespace nq {

inline constexpr int kMaxEntityLights = NQR_MAX_ENTITY_LIGHTS;
inline constexpr int kMaxLightCandidates = 8;
// Keys of dynamic lights: this bit, or'ed with their index in the frame's list.
inline constexpr uint32_t kDynamicLightKey = 0x80000000u;

struct LightContribution {
    uint32_t key = 0;  // index into the light entities, or kDynamicLightKey | dlight index
    glm::vec3 position{0.0f};
    glm::vec3 color{0.0f};  // light units / 128, everything applied
    float strength = 0.0f;  // mean of color's channels
};

// A fixed-size list, strongest first.
struct LightContributions {
    std::array<LightContribution, kMaxEntityLights> items{};
    int count = 0;
};

// Inserts `light` into `list` when it is among the kMaxEntityLights strongest (strength > 0).
void keep_strongest(LightContributions& list, const LightContribution& light);

// A light entity's level (light units) at `distance`, before style, colour and occlusion.
float light_level(const LightEntity& light, float distance);

// The strongest lights at `point` (see above).
// The light entities' visibilities it traces go to `traced` when given.
LightContributions strongest_lights(const Bsp& bsp, std::span<const LightEntity> lights,
                                    const glm::vec3& point, std::span<const float> lightstyles,
                                    DlightList dlights, VisibilityCache* traced = nullptr);

// Writes `lights` into out.num_lights / out.lights (sizes included), as they are.
void store_lights(const LightContributions& lights, EntityLighting& out);

}  // namespace nq

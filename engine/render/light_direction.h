// Where the light at a point comes from, for directional shading of models.
//
// Each light entity i (light_entities.h) at distance d_i, seen from the point, weighs
//     w_i = brightness_i * lightstyles[style_i] * fade_i(d_i) * visible_i / (d_i^2 + 64^2)
// where fade_i is 1 up to half the light's reach and falls smoothly (smoothstep) to 0 at its
// reach (linear lights: brightness / wait; others: kMaxLightRange), and visible_i is the
// fraction of kVisibilityProbes points around the light (its origin and four points
// kProbeOffset units away across the line of sight) that a hull-0 trace from the point reaches,
// or stops within kProbeSlack units of (lights are often placed in or against a ceiling).
// Dynamic lights weigh the same way with brightness = radius and no occlusion test.
// The direction is
//     normalize(sum_i w_i * unit(light_i - point) + kSkyWeight * (0, 0, 1))
// The small sky term (a 300-unit light 2048 units straight above) makes the result fall back
// smoothly to "from above" when no light is near, and keeps it defined when lights cancel.
//
// Every term changes continuously with the point except visible_i, which steps by 1/5 of one
// light's share where the point crosses a shadow edge, and the choice of the kMaxTracedLights
// heaviest lights to trace. No stateless rule can do better with binary line-of-sight tests, so
// entities that move keep a LightSmoother (light_smoother.h) that turns toward each new result
// over a fraction of a second: that is what makes the direction never jump.
#pragma once

#include <array>
#include <cstdint>
#include <span>

#include <glm/glm.hpp>

#include "formats/bsp.h"
#include "nqr_renderer.h"
#include "render/light_entities.h"

namespace nq {

inline constexpr float kMaxLightRange = 2048.0f;
inline constexpr float kLightDistanceSoftening = 64.0f;
inline constexpr float kSkyWeight = 300.0f / (2048.0f * 2048.0f);
inline constexpr int kVisibilityProbes = 5;
inline constexpr float kProbeOffset = 16.0f;
inline constexpr float kProbeSlack = 16.0f;
inline constexpr int kMaxTracedLights = 4;

// Array of nqr_dlight walked with its size field as the stride (nqr_at).
struct DlightList {
    const nqr_dlight* first = nullptr;
    uint32_t count = 0;
};

// Visibilities (light_visibility) of light entities already traced from one point, by index
// into the lights: the strongest-lights list traces the same lights the direction does.
struct VisibilityCache {
    static constexpr int kCapacity = 8;
    std::array<uint32_t, kCapacity> light{};
    std::array<float, kCapacity> visibility{};
    int count = 0;

    const float* find(uint32_t index) const {
        for (int i = 0; i < count; ++i) {
            if (light[i] == index) return &visibility[i];
        }
        return nullptr;
    }
    void add(uint32_t index, float value) {
        if (count == kCapacity) return;
        light[count] = index;
        visibility[count++] = value;
    }
};

// visible_i above: the fraction (0..1, in steps of 1 / kVisibilityProbes) of the probe points
// around a light at `light` that `point` sees.
float light_visibility(const Bsp& bsp, const glm::vec3& point, const glm::vec3& light);

// The weight of a light of `brightness` and `reach` at `distance`, before occlusion.
float light_weight(float brightness, float reach, float distance);

// Unit vector from `point` toward where its light comes from (see above). Visibilities found
// in `traced` (taken at this point, for these lights) are not traced again. Allocation-free.
glm::vec3 dominant_light_direction(const Bsp& bsp, std::span<const LightEntity> lights,
                                   const glm::vec3& point, std::span<const float> lightstyles,
                                   DlightList dlights, const VisibilityCache* traced = nullptr);

}  // namespace nq

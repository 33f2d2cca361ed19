// The ambient cube of any point of a map, from the samples baked at level load
// (ambient_cube_bake.h).
//
// LOOKUP. The samples within kBlendRadius of the point are blended with Source's weight
// 1 / (d^2 + 1), the distance d measured in units of kBlendScale world units, times a window
// that is 1 up to half the radius and falls smoothly (smoothstep) to 0 at the radius, so a
// sample entering or leaving the radius changes nothing abruptly:
//     w = window(d) / ((d / kBlendScale)^2 + 1),   cube = sum w_i cube_i / sum w_i
// Only the kMaxBlendedSamples heaviest count, and only those the point sees (a hull-0 trace
// from the point reaches them): light does not leak through walls from the room next door.
// Samples in the point's own (convex) leaf are always seen. Nothing in the blend depends on
// which leaf the point is in, so the cube varies smoothly as an entity crosses leaf boundaries;
// it steps only where a sample goes out of sight, which the entity's LightSmoother smooths.
// A point with no seen sample within the radius (inside a wall, or in a leaf too small to be
// sampled) takes the nearest sample within kFallbackRings grid cells; beyond that it has none.
//
// Allocation-free; the field is immutable after construction, so lookups may run on threads.
#pragma once

#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "formats/bsp.h"
#include "render/ambient_cube.h"
#include "render/ambient_cube_bake.h"
#include "render/point_grid.h"

namespace nq {

inline constexpr float kBlendRadius = 256.0f;
inline constexpr float kBlendScale = 32.0f;
inline constexpr int kMaxBlendedSamples = 12;
inline constexpr int kFallbackRings = 4;

// The weight of a sample at `distance` (before the line-of-sight test).
float ambient_sample_weight(float distance);

class AmbientCubeField {
  public:
    AmbientCubeField() = default;
    // Keeps a reference to `bsp` (for line-of-sight tests), which must outlive the field.
    AmbientCubeField(const Bsp& bsp, std::vector<AmbientSample> samples);

    // Bakes the samples of `bsp` (see ambient_cube_bake.h for `rgb` and `reflectivity`).
    static AmbientCubeField bake(const Bsp& bsp, std::span<const uint8_t> rgb,
                                 std::span<const glm::vec3> reflectivity,
                                 const AmbientBakeSettings& settings = {});

    // The blended cube at `point` (light units); false, and `out` all zero, when no sample is
    // near enough.
    bool cube_at(const glm::vec3& point, AmbientCube& out) const;

    std::span<const AmbientSample> samples() const { return samples_; }
    bool empty() const { return samples_.empty(); }

  private:
    struct Weighted {
        uint32_t sample = 0;
        float weight = 0.0f;
    };
    int heaviest_near(const glm::vec3& point, Weighted* out) const;
    bool sees(const glm::vec3& point, const AmbientSample& sample) const;
    bool nearest_fallback(const glm::vec3& point, AmbientCube& out) const;

    const Bsp* bsp_ = nullptr;
    std::vector<AmbientSample> samples_;
    PointGrid grid_;
};

}  // namespace nq

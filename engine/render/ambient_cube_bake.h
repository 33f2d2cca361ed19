// Baking the ambient cube field at level load, as Source's light compiler does for its per-leaf
// ambient samples: from every sample point (ambient_sample_points.h) rays go out over an evenly
// spread direction set (sphere_directions.h: 162, or 42 from small leafs). A ray reads
//     the lightmap where it first meets a lit surface (lightmap_probe.h: bilinear, the light
//       arriving there) times the surface's reflectivity (surface_reflectivity.h), i.e. the
//       light that surface sends back;
//     sky_level times the sky texture's colour where it meets a sky surface;
//     nothing where it meets no surface within ray_length.
// A map without lighting counts every lit surface at Quake's full level (255), as
// R_LightPoint does.
//
// LIGHT STYLES. The field is baked once, with every light style at its normal value 1: light
// from switchable and flickering (animated) styles is in it at normal strength and does not
// follow the style at run time (the level, direction and light list of an entity do).
//
// Each face of the cube then gathers the rays with cosine weights:
//     face_f = sum_i L_i * max(0, dot(d_i, axis_f)) / sum_i max(0, dot(d_i, axis_f))
// the irradiance of a surface facing axis_f, normalised so that light L from every direction
// gives L on every face. Values stay in Quake light units (128 = normal).
//
// The points are shared among std::thread workers (one per hardware core, or `threads`); the
// result does not depend on their number.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "formats/bsp.h"
#include "render/ambient_cube.h"
#include "render/ambient_sample_points.h"

namespace nq {

inline constexpr float kUnlitSurfaceLevel = 255.0f;

struct AmbientBakeSettings {
    float sample_spacing = kDefaultSampleSpacing;
    int direction_level = 2;             // 162 directions
    int small_leaf_direction_level = 1;  // 42 directions
    float sky_level = 128.0f;            // light units the sky sends, times its texture's colour
    float ray_length = 8192.0f;
    unsigned threads = 0;  // 0: std::thread::hardware_concurrency()
};

struct AmbientSample {
    glm::vec3 position{0.0f};
    uint32_t leaf = 0;
    AmbientCube cube;
};

// What one ray or one point gathers; immutable once built, shared by the workers.
class AmbientGatherer {
  public:
    // `rgb`: 3 bytes per lightmap sample (empty for an unlit map); `reflectivity`: one RGB per
    // texture (texture_reflectivity). Both must outlive the gatherer.
    AmbientGatherer(const Bsp& bsp, std::span<const uint8_t> rgb,
                    std::span<const glm::vec3> reflectivity, const AmbientBakeSettings& settings);

    // Light (light units) arriving at `point` from unit direction `direction`.
    glm::vec3 radiance(const glm::vec3& point, const glm::vec3& direction) const;
    // The cube at `point`, from the full or the small direction set.
    AmbientCube gather(const glm::vec3& point, bool small_set = false) const;

  private:
    struct DirectionSet {
        std::vector<glm::vec3> directions;
        std::array<float, kCubeFaces> normaliser{};  // 1 / sum of each face's weights
    };
    static DirectionSet make_set(int level);
    glm::vec3 reflectivity_of(uint32_t face) const;

    const Bsp& bsp_;
    std::span<const uint8_t> rgb_;
    std::span<const glm::vec3> reflectivity_;
    AmbientBakeSettings settings_;
    std::vector<float> styles_;  // every style at 1
    DirectionSet full_, small_;
};

// Every sample of the map (ambient_sample_points order) with its cube.
std::vector<AmbientSample> bake_ambient_samples(const Bsp& bsp, std::span<const uint8_t> rgb,
                                                std::span<const glm::vec3> reflectivity,
                                                const AmbientBakeSettings& settings = {});

}  // namespace nq

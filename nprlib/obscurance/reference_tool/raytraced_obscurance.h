// The volumetric obscurance of a frame's real geometry, ray-traced with Embree: for each
// pixel, the camera ray finds the nearest surface P (sky and liquid ones are open, as the
// screen-space pass leaves them out); then directions spread evenly over the hemisphere above
// P's face are traced up to the radius R. The part of the ball above P's tangent plane that P
// sees is star-shaped around P, so its volume fraction is the mean over directions of
// (min(hit distance, R) / R)^3: no thickness, no depth buffer, the geometry itself.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "obscurance/scene_file.h"

namespace nq::npr::obscurance {

struct RaytraceOptions {
    float radius = 24.0f;
    int directions_per_side = 24;  // a side x side grid over the hemisphere (576 rays)
    int threads = 0;               // 0: the machine's
};

struct RaytraceResult {
    std::vector<float> open;  // width x height, GL order (bottom row first), 1 = open
    std::string error;        // Embree refused the scene or the device
};

RaytraceResult raytrace_obscurance(const ObscuranceScene& scene, const RaytraceOptions& options);

}  // namespace nq::npr::obscurance

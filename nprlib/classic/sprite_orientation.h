// The axes a sprite quad is spanned by, for Quake's five sprite types:
//   0 parallel upright  — faces the view plane, stays vertical: up = world +Z, right = view right
//   1 facing upright    — turns about +Z toward the eye: right is perpendicular to the
//                         horizontal eye-to-sprite direction, up = +Z
//   2 parallel          — the view plane's right and up (the usual billboard)
//   3 oriented          — the entity's own right and up from its angles
//   4 parallel oriented — the view plane's axes rolled by the entity's roll angle
#pragma once

#include <glm/vec3.hpp>

namespace nq::npr::classic {

enum class SpriteType : unsigned {
    parallel_upright = 0,
    facing_upright = 1,
    parallel = 2,
    oriented = 3,
    parallel_oriented = 4
};

struct SpriteAxes {
    glm::vec3 right, up;
};

struct SpriteView {
    glm::vec3 eye, right, up;  // camera origin and axes, Quake world space
};

// Quake's AngleVectors: (pitch, yaw, roll) in degrees -> forward, right, up.
void quake_angle_vectors(const glm::vec3& angles, glm::vec3* forward, glm::vec3* right,
                         glm::vec3* up);

// Unknown types are drawn as `parallel`.
SpriteAxes sprite_axes(unsigned type, const SpriteView& view, const glm::vec3& origin,
                       const glm::vec3& angles);

}  // namespace nq::npr::classic

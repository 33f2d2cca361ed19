#include "classic/sprite_orientation.h"

#include <cmath>

#include <glm/geometric.hpp>

namespace nq::npr::classic {
namespace {

constexpr float kDegreesToRadians = 3.14159265358979f / 180.0f;

SpriteAxes facing_upright(const SpriteView& view, const glm::vec3& origin) {
    glm::vec3 toward(origin.x - view.eye.x, origin.y - view.eye.y, 0.0f);
    const float length = glm::length(toward);
    if (length < 1e-6f) return {view.right, glm::vec3(0, 0, 1)};
    toward /= length;
    return {glm::vec3(toward.y, -toward.x, 0.0f), glm::vec3(0, 0, 1)};
}

SpriteAxes parallel_oriented(const SpriteView& view, float roll_degrees) {
    const float roll = roll_degrees * kDegreesToRadians;
    const float s = std::sin(roll), c = std::cos(roll);
    return {view.right * c + view.up * s, view.up * c - view.right * s};
}

}  // namespace

void quake_angle_vectors(const glm::vec3& angles, glm::vec3* forward, glm::vec3* right,
                         glm::vec3* up) {
    const float pitch = angles.x * kDegreesToRadians;
    const float yaw = angles.y * kDegreesToRadians;
    const float roll = angles.z * kDegreesToRadians;
    const float sp = std::sin(pitch), cp = std::cos(pitch);
    const float sy = std::sin(yaw), cy = std::cos(yaw);
    const float sr = std::sin(roll), cr = std::cos(roll);
    if (forward) *forward = {cp * cy, cp * sy, -sp};
    if (right) *right = {-sr * sp * cy + cr * sy, -sr * sp * sy - cr * cy, -sr * cp};
    if (up) *up = {cr * sp * cy + sr * sy, cr * sp * sy - sr * cy, cr * cp};
}

SpriteAxes sprite_axes(unsigned type, const SpriteView& view, const glm::vec3& origin,
                       const glm::vec3& angles) {
    switch (static_cast<SpriteType>(type)) {
        case SpriteType::parallel_upright:
            return {view.right, glm::vec3(0, 0, 1)};
        case SpriteType::facing_upright:
            return facing_upright(view, origin);
        case SpriteType::oriented: {
            SpriteAxes axes;
            quake_angle_vectors(angles, nullptr, &axes.right, &axes.up);
            return axes;
        }
        case SpriteType::parallel_oriented:
            return parallel_oriented(view, angles.z);
        case SpriteType::parallel:
            break;
    }
    return {view.right, view.up};
}

}  // namespace nq::npr::classic

// View frustum planes in Quake world space, for culling boxes (BSP nodes and leafs, entities).
#pragma once

#include <array>
#include <cstdint>

#include <glm/glm.hpp>

namespace nq {

// Points p with dot(normal, p) - dist >= 0 are on the inner side.
struct FrustumPlane {
    glm::vec3 normal{0.0f};
    float dist = 0.0f;
};

struct Frustum {
    // Left, right, bottom, top, near, far.
    std::array<FrustumPlane, 6> planes{};
    uint32_t num_planes = 0;  // 0 = nothing is culled

    // The six planes of a (GL, -w..w depth) view-projection matrix, normalised. Because the
    // matrix maps world positions to clip space, the planes come out in world space.
    static Frustum from_view_projection(const glm::mat4& view_projection);
    // Only the four side planes (Quake culls nothing by distance).
    static Frustum sides_from_view_projection(const glm::mat4& view_projection);

    // True when the axis-aligned box lies wholly outside one plane (conservative: a box near a
    // frustum corner may be kept although it is outside).
    bool box_outside(const glm::vec3& mins, const glm::vec3& maxs) const;
    // True when the sphere lies wholly outside one plane (conservative, as box_outside).
    bool sphere_outside(const glm::vec3& centre, float radius) const;
    // True when the box [mins, maxs] of an object's own space, placed in the world by the affine
    // `object_to_world` (rotation, scale, translation), lies wholly outside one plane
    // (conservative, as box_outside).
    bool placed_box_outside(const glm::mat4& object_to_world, const glm::vec3& mins,
                            const glm::vec3& maxs) const;
};

}  // namespace nq

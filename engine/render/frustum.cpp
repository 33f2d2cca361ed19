#include "render/frustum.h"

#include <cmath>

namespace nq {

namespace {

// Gribb and Hartmann: with clip = M * p, the plane of clip.x >= -clip.w is row3 + row0, and so on.
FrustumPlane plane_from_rows(const glm::mat4& m, int row, float sign) {
    glm::vec4 coefficients;
    for (int c = 0; c < 4; ++c) coefficients[c] = m[c][3] + sign * m[c][row];
    const glm::vec3 normal(coefficients);
    const float length = glm::length(normal);
    if (length <= 0.0f) return {};  // degenerate matrix: a plane that keeps everything
    return {normal / length, -coefficients.w / length};
}

}  // namespace

Frustum Frustum::from_view_projection(const glm::mat4& view_projection) {
    Frustum f;
    for (int row = 0; row < 3; ++row) {
        f.planes[f.num_planes++] = plane_from_rows(view_projection, row, 1.0f);
        f.planes[f.num_planes++] = plane_from_rows(view_projection, row, -1.0f);
    }
    return f;
}

Frustum Frustum::sides_from_view_projection(const glm::mat4& view_projection) {
    Frustum f = from_view_projection(view_projection);
    f.num_planes = 4;
    return f;
}

bool Frustum::box_outside(const glm::vec3& mins, const glm::vec3& maxs) const {
    for (uint32_t i = 0; i < num_planes; ++i) {
        const FrustumPlane& p = planes[i];
        // The corner furthest along the normal: if even it is behind, the whole box is.
        const glm::vec3 corner(p.normal.x >= 0 ? maxs.x : mins.x, p.normal.y >= 0 ? maxs.y : mins.y,
                               p.normal.z >= 0 ? maxs.z : mins.z);
        if (glm::dot(p.normal, corner) - p.dist < 0.0f) return true;
    }
    return false;
}

bool Frustum::sphere_outside(const glm::vec3& centre, float radius) const {
    for (uint32_t i = 0; i < num_planes; ++i) {
        if (glm::dot(planes[i].normal, centre) - planes[i].dist < -radius) return true;
    }
    return false;
}

bool Frustum::placed_box_outside(const glm::mat4& object_to_world, const glm::vec3& mins,
                                 const glm::vec3& maxs) const {
    const glm::vec3 centre(object_to_world * glm::vec4((mins + maxs) * 0.5f, 1.0f));
    const glm::vec3 half = (maxs - mins) * 0.5f;
    for (uint32_t i = 0; i < num_planes; ++i) {
        const FrustumPlane& p = planes[i];
        // How far the box reaches along the normal from its centre: its half axes, placed.
        float reach = 0.0f;
        for (int axis = 0; axis < 3; ++axis) {
            reach += half[axis] * std::abs(glm::dot(p.normal, glm::vec3(object_to_world[axis])));
        }
        if (glm::dot(p.normal, centre) - p.dist < -reach) return true;
    }
    return false;
}

}  // namespace nq

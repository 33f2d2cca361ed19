#include "technical/alias_pose.h"

#include <algorithm>
#include <cstddef>

namespace nq::npr::technical {

void blend_alias_pose(const nqr_alias_model& model, const nqr_entity& entity, glm::vec3* out) {
    if (model.num_poses == 0) return;
    const uint32_t last = model.num_poses - 1;
    const nqr_alias_vertex* pose0 =
        model.poses + size_t(std::min(entity.pose0, last)) * model.num_vertices;
    const nqr_alias_vertex* pose1 =
        model.poses + size_t(std::min(entity.pose1, last)) * model.num_vertices;
    const float t = std::clamp(entity.lerp, 0.0f, 1.0f);
    const glm::vec3 scale(model.scale[0], model.scale[1], model.scale[2]);
    const glm::vec3 origin(model.origin[0], model.origin[1], model.origin[2]);
    for (uint32_t v = 0; v < model.num_vertices; ++v) {
        const glm::vec3 a(pose0[v].v[0], pose0[v].v[1], pose0[v].v[2]);
        const glm::vec3 b(pose1[v].v[0], pose1[v].v[1], pose1[v].v[2]);
        out[v] = scale * (a + (b - a) * t) + origin;
    }
}

}  // namespace nq::npr::technical

#include "technical/alias_pose.h"

#include <algorithm>
#include <cstddef>

#include "classic/alias_mesh.h"

namespace nq::npr::technical {
namespace {

struct PosePair {
    uint32_t pose0 = 0, pose1 = 0;
    float lerp = 0.0f;
};

PosePair clamped_poses(const nqr_alias_model& model, const nqr_entity& entity) {
    const uint32_t last = model.num_poses - 1;
    return {std::min(entity.pose0, last), std::min(entity.pose1, last),
            std::clamp(entity.lerp, 0.0f, 1.0f)};
}

}  // namespace

void blend_alias_pose(const nqr_alias_model& model, const nqr_entity& entity, glm::vec3* out) {
    if (model.num_poses == 0) return;
    const PosePair poses = clamped_poses(model, entity);
    const nqr_alias_vertex* pose0 = model.poses + size_t(poses.pose0) * model.num_vertices;
    const nqr_alias_vertex* pose1 = model.poses + size_t(poses.pose1) * model.num_vertices;
    const float t = poses.lerp;
    const glm::vec3 scale(model.scale[0], model.scale[1], model.scale[2]);
    const glm::vec3 origin(model.origin[0], model.origin[1], model.origin[2]);
    for (uint32_t v = 0; v < model.num_vertices; ++v) {
        const glm::vec3 a(pose0[v].v[0], pose0[v].v[1], pose0[v].v[2]);
        const glm::vec3 b(pose1[v].v[0], pose1[v].v[1], pose1[v].v[2]);
        out[v] = scale * (a + (b - a) * t) + origin;
    }
}

PoseNormals::PoseNormals(const nqr_alias_model& model, std::span<const uint8_t> pose_texels,
                         const nqr_entity& entity) {
    const size_t per_pose = size_t(model.num_vertices) * classic::kPoseTexelsPerVertex * 4;
    if (model.num_poses == 0 || pose_texels.size() < per_pose * model.num_poses) return;
    const PosePair poses = clamped_poses(model, entity);
    // The normal is each vertex's second texel.
    pose0_ = pose_texels.data() + per_pose * poses.pose0 + 4;
    pose1_ = pose_texels.data() + per_pose * poses.pose1 + 4;
    lerp_ = poses.lerp;
}

glm::vec3 PoseNormals::at(uint32_t vertex) const {
    const size_t texel = size_t(vertex) * classic::kPoseTexelsPerVertex * 4;
    const uint8_t* a = pose0_ + texel;
    const uint8_t* b = pose1_ + texel;
    glm::vec3 n0, n1;
    for (int i = 0; i < 3; ++i) {
        n0[i] = classic::decode_normal_component(a[i]);
        n1[i] = classic::decode_normal_component(b[i]);
    }
    return n0 + (n1 - n0) * lerp_;
}

}  // namespace nq::npr::technical

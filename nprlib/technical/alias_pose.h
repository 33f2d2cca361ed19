// An entity's alias pose blended on the CPU, once per frame: the shadow drawer flattens it and
// the edge drawer finds silhouettes and creases on it and shades their ends (the face drawer
// blends on the GPU).
#pragma once

#include <cstdint>
#include <span>

#include <glm/vec3.hpp>

#include "nqr_renderer.h"

namespace nq::npr::technical {

// Writes model.num_vertices model-space positions: pose0 * (1 - lerp) + pose1 * lerp, poses
// and lerp clamped as classic::set_alias_pose_uniforms clamps them for the GPU.
void blend_alias_pose(const nqr_alias_model& model, const nqr_entity& entity, glm::vec3* out);

// The entity's vertex normals between its two poses, read from the packed pose texels
// (classic::AliasModelGpu::pose_texels) and blended as the GPU pose library blends them:
// mix(n0, n1, lerp), not renormalised.
class PoseNormals {
  public:
    PoseNormals(const nqr_alias_model& model, std::span<const uint8_t> pose_texels,
                const nqr_entity& entity);
    bool valid() const { return pose0_ != nullptr; }
    glm::vec3 at(uint32_t vertex) const;

  private:
    const uint8_t* pose0_ = nullptr;
    const uint8_t* pose1_ = nullptr;
    float lerp_ = 0.0f;
};

}  // namespace nq::npr::technical

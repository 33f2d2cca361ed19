// An entity's alias pose blended on the CPU, once per frame: the shadow drawer flattens it and
// the edge drawer finds silhouettes and creases on it (the face drawer blends on the GPU).
#pragma once

#include <cstdint>

#include <glm/vec3.hpp>

#include "nqr_renderer.h"

namespace nq::npr::technical {

// Writes model.num_vertices model-space positions: pose0 * (1 - lerp) + pose1 * lerp, poses
// and lerp clamped as classic::set_alias_pose_uniforms clamps them for the GPU.
void blend_alias_pose(const nqr_alias_model& model, const nqr_entity& entity, glm::vec3* out);

}  // namespace nq::npr::technical

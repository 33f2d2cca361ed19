// GLSL for alias-model vertex shaders: an MDL vertex's position and normal blended between the
// entity's two poses, read from AliasModelGpu's pose buffer texture. Shared by the classic drawer
// and every NPR drawer that draws alias models (faces, edges, shadows). Paste
// kAliasPoseLibrary after the #version line; set_alias_pose_uniforms() fills its uniforms and
// binds the pose texture to `unit`.
#pragma once

#include <cstdint>

#include "classic/alias_model_gpu.h"
#include "gl/program.h"
#include "nqr_renderer.h"

namespace nq::npr::classic {

// Declares (GLSL):
//   uniform usamplerBuffer u_poses; uniform int u_num_vertices, u_pose0, u_pose1;
//   uniform float u_lerp; uniform vec3 u_scale, u_origin;
//   vec3 pose_position(int mdl_vertex)   model space (scale * packed + origin), blended
//   vec3 pose_normal(int mdl_vertex)     model space, blended (not renormalised)
extern const char* const kAliasPoseLibrary;

// Pose indices clamped into the model, lerp clamped to 0..1. The program must be in use and
// its u_poses sampler set to `unit`.
void set_alias_pose_uniforms(gl::Program& program, const AliasModelGpu& model,
                             const nqr_entity& entity, int unit);

}  // namespace nq::npr::classic

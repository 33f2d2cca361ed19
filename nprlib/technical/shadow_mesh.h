// The triangles a model casts its shadow with. A shadow is a flat dark blob under the model,
// its outline softened by the penumbra; it does not need every triangle of the model, and on a
// software rasteriser the many small triangles of three projections per model cost more than
// any other part of the style. Models with more than kShadowKeepAll triangles cast their shadow
// with a simplified copy of the welded mesh (OpenMesh's quadric decimater on pose 0): a fifth
// of the triangles (a third cost 2 million instructions a frame more in demo.dem and looked the
// same under the penumbra), every one still made of the model's own vertices, so the shadow
// follows the animation.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "adjacency/mesh_builder.h"

namespace nq::npr::technical {

inline constexpr size_t kShadowKeepAll = 64;         // meshes this small are used as they are
inline constexpr float kShadowTriangleShare = 0.2f;  // of bigger meshes, about this share

// Counter-clockwise seen from outside, in MDL vertex indices; empty when the mesh has no
// faces. Deterministic for a given mesh.
std::vector<std::array<uint32_t, 3>> shadow_triangles(const adjacency::BuiltMesh& built);

}  // namespace nq::npr::technical

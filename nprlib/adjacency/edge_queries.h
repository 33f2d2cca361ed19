// The per-frame questions a renderer asks of the precomputed edge data; no allocation (output
// vectors are cleared and refilled: reserve once) and no adjacency work.
//
// SILHOUETTES. An edge is on the silhouette when one of its faces looks toward the eye and the
// other away: (n0·(e − p0)) (n1·(e − p1)) ≤ 0, with e the eye in model space and p_i any point
// of face i. The shorter (n0·e)(n1·e) ≤ 0 is only right when e is a direction (an eye at
// infinity) or when both planes pass through the origin; for a real eye at a finite distance it
// marks the wrong edges as soon as the model is not centred on the origin, so the planes carry
// their distance (FacePlane). Boundary edges are always on the outline.
//
// CREASES. An edge whose faces bend by at least the user's threshold angle is a crease: a ridge
// where the surface is convex there, a valley where concave (PoseGeometry::dihedral's sign).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "adjacency/edge_table.h"
#include "adjacency/pose_geometry.h"

namespace nq::npr::adjacency {

// Signed distance of the eye from the face's plane: > 0 when the face looks toward the eye.
inline float eye_height(const FacePlane& plane, const glm::vec3& eye) {
    return glm::dot(plane.normal, eye) - plane.distance;
}

bool is_silhouette(const MeshEdge& edge, const PoseGeometry& geometry, uint32_t pose,
                   const glm::vec3& eye);

// Edge indices on the silhouette of `pose` seen from `eye` (model space).
void find_silhouette_edges(const EdgeTable& table, const PoseGeometry& geometry, uint32_t pose,
                           const glm::vec3& eye, std::vector<uint32_t>& out);

// The same while the engine blends pose0 * (1 - lerp) + pose1 * lerp: each face's eye height is
// blended the same way (exact at lerp 0 and 1, a close approximation between).
void find_silhouette_edges_blended(const EdgeTable& table, const PoseGeometry& geometry,
                                   uint32_t pose0, uint32_t pose1, float lerp, const glm::vec3& eye,
                                   std::vector<uint32_t>& out);

enum class Crease : uint8_t { none, ridge, valley };
const char* crease_name(Crease crease);

inline Crease classify_crease(float signed_dihedral, float threshold_radians) {
    if (signed_dihedral >= threshold_radians) return Crease::ridge;
    if (-signed_dihedral >= threshold_radians) return Crease::valley;
    return Crease::none;
}

// Edge indices of the ridges and valleys of `pose` for a threshold angle in radians (> 0).
void find_creases(const PoseGeometry& geometry, uint32_t pose, float threshold_radians,
                  std::vector<uint32_t>& ridges, std::vector<uint32_t>& valleys);

}  // namespace nq::npr::adjacency

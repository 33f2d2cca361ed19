// Per-pose geometry of the recovered mesh, precomputed once per model so that drawing a frame
// does no adjacency or normal work: every face's plane and every edge's signed dihedral angle
// in every pose. Positions are model space (scale * packed + origin), the space in which the
// engine gives a renderer the eye (nqr_entity.eye_model).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "adjacency/alias_source.h"
#include "adjacency/edge_table.h"
#include "adjacency/mesh_builder.h"

namespace nq::npr::adjacency {

// The plane dot(normal, x) = distance through a face; normal is unit length and points out of
// the face's front (outside), or is zero when the face has no area in that pose.
struct FacePlane {
    glm::vec3 normal{0.0f};
    float distance = 0.0f;
};

struct PoseGeometry {
    uint32_t num_poses = 0, num_faces = 0, num_edges = 0;
    std::vector<FacePlane> planes;  // [pose * num_faces + face]
    // [pose * num_edges + edge]: the angle between the two face normals, in radians, positive
    // where the edge is convex (a ridge), negative where concave (a valley), 0 where flat, on
    // a boundary, or when a face has no area in that pose.
    std::vector<float> dihedral;

    const FacePlane& plane(uint32_t pose, uint32_t face) const {
        return planes[size_t(pose) * num_faces + face];
    }
    float signed_dihedral(uint32_t pose, uint32_t edge) const {
        return dihedral[size_t(pose) * num_edges + edge];
    }
};

PoseGeometry compute_pose_geometry(const AliasSource& source, const BuiltMesh& built,
                                   const EdgeTable& edges);

}  // namespace nq::npr::adjacency

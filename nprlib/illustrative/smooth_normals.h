// Smooth per-vertex normals for alias model poses that keep sharp creases.
//
// Quake's 162-entry normal table is quantised and ignores seams; the TF2 look (rim light,
// Phong, the light warp) wants smooth normals that do not break along skin seams but do keep
// hard edges (a crate's corners, a blade's ridge). So:
//   - corners are grouped per *welded* vertex (adjacency/weld.h: MDL vertices equal in every
//     pose, the way LibreQuake stores UV seams), so both copies of a seam vertex share normals;
//   - around a welded vertex, faces that share an edge through it join one smoothing group
//     unless their normals differ by more than a crease angle (default 60 degrees);
//   - a vertex gets the angle-weighted average of its own group's face normals (angle weights
//     do not depend on how a face was split into triangles).
// The grouping must be the same in every pose (one vertex layout for all per-pose buffers), so
// an edge is a crease when it is sharper than the angle in at least half of the poses where both
// faces have area: a joint bending in a few frames stays smooth, a rigid ridge stays sharp.
// A triangle with no area in any pose joins no group (its corners take their welded vertex's
// mean normal), so it cannot bridge a crease it lies on.
//
// Vertex layout: the drawn vertices of classic::AliasMesh come first, in the same order (so
// the classic uv / pose_vertex attributes still apply); a drawn vertex whose corners fall into
// more than one group gets extra copies appended after them. `SmoothingLayout::indices` then
// replaces AliasMesh::indices. With crease_degrees >= 180 no edge is a crease, so copies are
// appended only where separate fans of faces touch at a single welded vertex.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "classic/alias_mesh.h"
#include "nqr_renderer.h"

namespace nq::npr::illustrative {

inline constexpr float kDefaultCreaseDegrees = 60.0f;

// The triangles as drawn. Triangles wind clockwise seen from outside (Quake's order, which
// AliasMesh::indices keeps), so cross(p2 - p0, p1 - p0) points outward.
struct SmoothingMesh {
    std::vector<uint32_t> indices;          // 3 per triangle: drawn vertex of each corner
    std::vector<uint32_t> vertex_position;  // per drawn vertex: its position (MDL vertex)
    std::vector<uint32_t> position_weld;    // per position: its welded vertex (class)
    uint32_t num_positions() const { return uint32_t(position_weld.size()); }
};

struct SmoothingLayout {
    std::vector<uint32_t> source_vertex;  // per shading vertex: the drawn vertex it copies
    std::vector<uint32_t> vertex_group;   // per shading vertex: its smoothing group (or kNoGroup)
    std::vector<uint32_t> indices;        // per corner: its shading vertex
    std::vector<uint32_t> corner_group;   // per corner: its smoothing group
    std::vector<uint32_t> group_weld;     // per group: its welded vertex
    uint32_t num_drawn_vertices = 0;
    std::string error;  // empty unless the mesh was inconsistent (then everything is empty)

    static constexpr uint32_t kNoGroup = UINT32_MAX;  // a drawn vertex no triangle uses
    uint32_t num_vertices() const { return uint32_t(source_vertex.size()); }
    uint32_t num_groups() const { return uint32_t(group_weld.size()); }
};

// Decides the smoothing groups from every pose. `poses` holds num_poses * num_positions
// positions, pose after pose.
SmoothingLayout plan_smoothing_groups(const SmoothingMesh& mesh, std::span<const glm::vec3> poses,
                                      uint32_t num_poses,
                                      float crease_degrees = kDefaultCreaseDegrees);

// One unit normal per shading vertex for one pose (`positions`: num_positions entries).
// Degenerate triangles add nothing; a vertex all of whose faces are degenerate takes the mean
// normal of its welded vertex, or +Z when there is none, so no normal is ever NaN.
void compute_smooth_normals(const SmoothingMesh& mesh, const SmoothingLayout& layout,
                            std::span<const glm::vec3> positions, std::vector<glm::vec3>& out);

// An alias model's smoothing mesh: AliasMesh's triangles and drawn vertices, welded with
// adjacency::weld_coincident_vertices.
SmoothingMesh alias_smoothing_mesh(const nqr_alias_model& model, const classic::AliasMesh& mesh);

// Model-space positions of every pose (num_poses x num_vertices), as plan_smoothing_groups
// takes them.
std::vector<glm::vec3> alias_pose_positions(const nqr_alias_model& model);

struct AliasSmoothNormals {
    SmoothingLayout layout;
    uint32_t num_poses = 0;
    std::vector<glm::vec3> normals;  // [pose * layout.num_vertices() + vertex], unit length

    const glm::vec3* pose(uint32_t p) const {
        return normals.data() + size_t(p) * layout.num_vertices();
    }
};

// Everything at once, for a model's load time.
AliasSmoothNormals compute_alias_smooth_normals(const nqr_alias_model& model,
                                                const classic::AliasMesh& mesh,
                                                float crease_degrees = kDefaultCreaseDegrees);

}  // namespace nq::npr::illustrative

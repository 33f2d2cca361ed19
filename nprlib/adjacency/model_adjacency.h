// Adjacency recovery for one alias model, done once at load time:
//   weld (weld.h) -> drop degenerates and duplicates (triangle_filter.h) -> orient
//   (orientation.h) -> OpenMesh half-edge mesh with vertex splits (mesh_builder.h) -> checks
//   (mesh_checks.h) -> edge table with the records a renderer tests per frame (edge_table.h)
//   -> the file's triangles with their side twins and seam representatives
//   (file_triangles.h) -> verdict (verdict.h); per-pose face planes and dihedral angles
//   (pose_geometry.h) only when asked for (reports, tests).
// Per frame a renderer classifies the records on its blended pose (feature_edges.h).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "adjacency/edge_table.h"
#include "adjacency/file_triangles.h"
#include "adjacency/mesh_builder.h"
#include "adjacency/pose_geometry.h"
#include "adjacency/recovery_stats.h"
#include "adjacency/verdict.h"
#include "nqr_renderer.h"

namespace nq::npr::adjacency {

struct ModelAdjacency {
    BuiltMesh mesh;
    // Per MDL vertex: the mesh vertex at its position (kNone when no kept triangle uses it).
    // A vertex on a split keeps the copy of the first face using it; face_corners and
    // face_vertices give every face's exact corners.
    std::vector<uint32_t> mdl_to_mesh_vertex;
    EdgeTable edges;
    FileTriangles file;
    PoseGeometry geometry;  // empty unless RecoveryOptions::pose_geometry
    RecoveryStats stats;
    std::vector<std::string> problems;  // from check_mesh: empty when every check passed
    Verdict verdict;
};

struct RecoveryOptions {
    double min_manifold_share = kMinManifoldShare;  // the verdict's threshold (verdict.h)
    bool pose_geometry = false;  // every pose's face planes and dihedrals: a renderer needs none
};

ModelAdjacency recover_adjacency(const nqr_alias_model& model, const RecoveryOptions& options = {});

// "adjacency: NAME: true silhouettes and creases (99.1% of 540 edges manifold and ...)".
std::string verdict_log_line(const std::string& model_name, const Verdict& verdict);

}  // namespace nq::npr::adjacency

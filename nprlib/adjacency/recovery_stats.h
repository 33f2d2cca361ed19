// What adjacency recovery did to one model, for reports, logs and the verdict.
#pragma once

#include <cstdint>

#include "adjacency/edge_census.h"
#include "adjacency/mesh_builder.h"
#include "adjacency/triangle_filter.h"

namespace nq::npr::adjacency {

struct RecoveryStats {
    uint32_t mdl_vertices = 0, triangles = 0, poses = 0;
    TriangleFilterCounts removed;  // degenerate and duplicate triangles dropped
    uint32_t welds = 0;            // MDL vertices merged into another (equal in every pose)
    uint32_t kept_apart = 0;       // merges a pose-0-only weld would make that later poses part
    uint32_t flipped_faces = 0;    // reversed to agree with their neighbours
    uint32_t orientation_conflicts = 0;
    SplitCounts splits;
    EdgeCensus soup;  // welded, filtered triangles in the file's orientation, before any split
    EdgeCensus mesh;  // the final mesh: no non-manifold edge, every interior edge consistent
    uint32_t mesh_vertices = 0, mesh_faces = 0;
    double seconds = 0.0;  // the whole recovery, wall clock
};

}  // namespace nq::npr::adjacency

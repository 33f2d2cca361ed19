// The 2005 NPRQuake's method, kept as a measured baseline: every frame, hash the edges of the
// triangle soup exactly as GLQuake draws it (every triangle of the file, degenerate and
// duplicated ones included, seam duplicates not merged by index) by the exact float positions
// of their endpoints in that frame, and read adjacency off the hash table. Its results change
// from frame to frame whenever parts touch in one pose and not in another.
#pragma once

#include <cstdint>

#include "adjacency/alias_source.h"
#include "adjacency/edge_census.h"

namespace nq::npr::adjacency {

// One frame's work for the paper's method: the census of edges keyed by endpoint positions.
EdgeCensus hash_edges_in_pose(const AliasSource& source, uint32_t pose);

struct BaselineReport {
    uint32_t poses = 0;
    EdgeCensus first_pose;  // pose 0
    EdgeCensus worst_pose;  // the pose with the lowest consistent share
    uint32_t worst_pose_index = 0;
    uint32_t poses_unlike_first = 0;  // poses whose census differs from pose 0's
    double seconds = 0.0;             // hashing every pose once, wall clock
};

BaselineReport run_paper_baseline(const AliasSource& source);

}  // namespace nq::npr::adjacency

// Welding an MDL's vertices by position across its whole animation.
//
// Two MDL vertices become one mesh vertex exactly when their packed (8-bit) coordinates are
// equal in every pose. Why exact equality and no tolerance: positions are stored on the
// model's 256^3 grid, so vertices the modeller meant to be one point (seam duplicates, the
// only way LibreQuake stores UV seams) were quantized from the same value and are bit-equal;
// any tolerance of even one grid step would merge genuinely distinct points, because one step
// is the model's finest resolution. Requiring equality in every pose, not just frame 0, means
// a weld never tears during animation (v_rock2.mdl and player.mdl have parts that touch in
// frame 0 and separate later).
#pragma once

#include <cstdint>
#include <vector>

#include "adjacency/alias_source.h"

namespace nq::npr::adjacency {

struct VertexWeld {
    std::vector<uint32_t> class_of;        // per MDL vertex: its welded vertex
    std::vector<uint32_t> representative;  // per welded vertex: its lowest MDL vertex index

    uint32_t num_classes() const { return static_cast<uint32_t>(representative.size()); }
    // MDL vertices merged into another one.
    uint32_t merged() const { return static_cast<uint32_t>(class_of.size()) - num_classes(); }
};

// Classes in order of their lowest MDL vertex. With no poses nothing is known about
// positions, so every vertex stays its own class.
VertexWeld weld_coincident_vertices(const AliasSource& source);

// The same weld judged on one pose only (what a frame-0 or per-frame weld would do): more
// merges whenever parts touch in that pose. For reports and tests.
VertexWeld weld_in_one_pose(const AliasSource& source, uint32_t pose);

}  // namespace nq::npr::adjacency

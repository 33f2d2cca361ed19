// Consistent orientation: across every edge shared by exactly two triangles, the two should
// traverse it in opposite directions. Triangles are flipped breadth-first from a seed per
// connected piece; each piece then keeps the orientation most of its triangles have in the
// file (Quake's outward winding), so a consistent file is never flipped. Edges shared by three
// or more triangles constrain nothing (mesh_builder splits them); where the surface is
// non-orientable some two-triangle edges stay inconsistent and are counted as conflicts.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "adjacency/triangle_filter.h"

namespace nq::npr::adjacency {

struct OrientationPlan {
    std::vector<uint32_t> order;   // soup triangle indices, piece by piece, breadth-first
    std::vector<uint8_t> flipped;  // per soup triangle: 1 = reversed relative to the file
    uint32_t flipped_count = 0;
    uint32_t conflicts = 0;   // two-triangle edges left traversed in the same direction
    uint32_t components = 0;  // pieces connected through two-triangle edges
};

OrientationPlan plan_orientation(std::span<const SoupTriangle> triangles);

}  // namespace nq::npr::adjacency

// Zero-area triangles, judged exactly on the packed grid.
#pragma once

#include <array>
#include <cstdint>

#include "adjacency/alias_source.h"

namespace nq::npr::adjacency {

// True when the three MDL vertices are collinear (or coincide) in every pose, i.e. the triangle
// never covers any area and can be dropped. A triangle flat in frame 0 that opens later is kept.
// The test is exact: the cross product of packed integer edge vectors, scaled per axis by the
// model's scale (an affine map keeps collinearity; a zero scale flattens that axis). A model
// with no poses has no known positions and nothing is judged degenerate.
bool zero_area_in_every_pose(const AliasSource& source, const std::array<uint32_t, 3>& vertices);

}  // namespace nq::npr::adjacency

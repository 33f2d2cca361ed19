// Where the ambient cube field (ambient_cube_field.h) samples the map's light: points in every
// open leaf of the world, as Source's light compiler places its per-leaf ambient samples.
//
// A leaf whose contents are not solid or sky (open air, water, slime, lava) is split along each
// axis into round(extent / spacing) cells, 1 to kMaxCellsPerAxis, of its bounding box; the
// centre of every cell that lies in the leaf itself (the box also covers neighbouring space) is
// a sample point. A leaf none of whose cell centres is inside gets one point "pulled" into it:
// the first of a few points between its box centre and the centroid of the vertices of its
// faces (which lie on the leaf's boundary, so their centroid is inside or on the convex leaf)
// that is in the leaf. A leaf with no such point, or with a box that is empty or not finite, has
// no sample: lookups then use its neighbours' samples.
//
// Small leafs (largest extent below kSmallLeafExtent) gather light with fewer rays.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "formats/bsp.h"

namespace nq {

inline constexpr float kDefaultSampleSpacing = 128.0f;
inline constexpr int kMaxCellsPerAxis = 4;
inline constexpr float kSmallLeafExtent = 64.0f;

struct AmbientSamplePoint {
    glm::vec3 position{0.0f};
    uint32_t leaf = 0;
    bool small_leaf = false;  // gathers with the smaller direction set
};

// Sample points of the world model's leafs, leaf by leaf in leaf order.
std::vector<AmbientSamplePoint> ambient_sample_points(const Bsp& bsp,
                                                      float spacing = kDefaultSampleSpacing);

// A point inside `leaf` near its middle, if one is found (see above).
bool point_inside_leaf(const Bsp& bsp, uint32_t leaf, glm::vec3& out);

}  // namespace nq

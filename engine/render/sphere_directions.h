// Evenly spread unit directions over the sphere: the vertices of a subdivided icosahedron, as
// light compilers use to gather the light arriving at a point (Source's vrad takes 162).
//
// Level 0 is the icosahedron's 12 vertices; each further level splits every triangle into four
// at its edge midpoints (pushed out onto the sphere), which adds one vertex per edge:
// 12 -> 42 -> 162 -> 642. The directions of a level are those of the level below followed by
// the new ones, so the first 12 (or 42) of a larger set are the smaller set.
#pragma once

#include <vector>

#include <glm/glm.hpp>

namespace nq {

inline constexpr int kMaxSphereLevel = 3;

// The number of directions at `level` (0..kMaxSphereLevel): 10 * 4^level + 2.
int sphere_direction_count(int level);

// The unit directions of a subdivided icosahedron at `level` (clamped to 0..kMaxSphereLevel).
std::vector<glm::vec3> sphere_directions(int level);

}  // namespace nq

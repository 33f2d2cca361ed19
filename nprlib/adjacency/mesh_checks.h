// Consistency checks on a built mesh, independent of how it was built: OpenMesh's own
// connectivity (every halfedge's opposite, next and prev agree; faces are triangles; no
// dangling edges or isolated vertices; OpenMesh's is_manifold at every vertex) and the face
// tables against it (each face's corners, no edge of the face list used by three faces).
#pragma once

#include <string>
#include <vector>

#include "adjacency/mesh_builder.h"

namespace nq::npr::adjacency {

// Empty when every check passes; otherwise one line per problem (at most kMaxProblems, then
// a line saying how many more).
std::vector<std::string> check_mesh(const BuiltMesh& built);

inline constexpr size_t kMaxProblems = 20;

}  // namespace nq::npr::adjacency

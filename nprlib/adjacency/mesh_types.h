// The half-edge mesh type every adjacency structure is built on.
#pragma once

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

namespace nq::npr::adjacency {

// OpenMesh's default triangle mesh: float points, faces counter-clockwise seen from the side
// their normal points to (outside, for a Quake model).
using TriMesh = OpenMesh::TriMesh_ArrayKernelT<>;

inline constexpr uint32_t kNone = UINT32_MAX;  // "no face" / "no vertex" in index tables

}  // namespace nq::npr::adjacency

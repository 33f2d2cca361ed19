// Where a new face goes in a mesh under construction: for each corner, which existing copy
// of its welded vertex to use, or a new copy (a vertex split). OpenMesh refuses a face whose
// edge already has a face on that side ("complex edge": a fin's third triangle, a surviving
// twin, a non-orientable seam) or whose corner is already surrounded by faces ("complex
// vertex"). Of the placements OpenMesh would accept, the one joining most edges wins, then the
// one splitting fewest vertices, then the one touching most existing vertices.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "adjacency/mesh_types.h"

namespace nq::npr::adjacency {

enum class Refusal { none, complex_edge, complex_vertex };

struct Placement {
    std::array<uint32_t, 3> vertices{};  // mesh vertex per corner; kNone: make a new copy
    uint32_t splits = 0;  // corners whose welded vertex already had a copy but gets a new one
    bool found = false;   // false: no acceptable placement among the copies tried
};

// Why OpenMesh would refuse a face on these corners (kNone corners are fresh vertices).
Refusal refusal_reason(const TriMesh& mesh, const std::array<uint32_t, 3>& vertices);

// `copies[i]`: the mesh vertices made so far for corner i's welded vertex.
Placement choose_placement(const TriMesh& mesh,
                           const std::array<const std::vector<uint32_t>*, 3>& copies);

}  // namespace nq::npr::adjacency

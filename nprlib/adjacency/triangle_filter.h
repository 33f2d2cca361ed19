// Which MDL triangles enter the mesh: degenerate ones and duplicates are dropped, each for a
// counted reason. Everything downstream works on welded vertex indices (weld.h).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "adjacency/alias_source.h"
#include "adjacency/weld.h"

namespace nq::npr::adjacency {

enum class TriangleFate : uint8_t {
    kept,
    bad_index,          // a vertex index outside the model (a broken ABI view)
    repeated_index,     // (a, a, b) or (a, a, a): the file repeats a vertex
    collapsed_by_weld,  // distinct vertices that coincide in every pose
    zero_area,          // collinear in every pose
    exact_duplicate,    // same welded vertices, same orientation as an earlier triangle
    back_to_back_twin,  // same welded vertices, opposite orientation (a double-sided sheet)
};
const char* fate_name(TriangleFate fate);

// A kept triangle in file order: clockwise seen from outside, as Quake stores it.
struct SoupTriangle {
    uint32_t mdl_triangle = 0;
    std::array<uint32_t, 3> mdl_vertices{};
    std::array<uint32_t, 3> welded{};
};

struct TriangleFilterCounts {
    uint32_t bad_index = 0, repeated_index = 0, collapsed_by_weld = 0, zero_area = 0;
    uint32_t exact_duplicates = 0, back_to_back_twins = 0;

    uint32_t degenerate() const { return repeated_index + collapsed_by_weld + zero_area; }
    uint32_t duplicates() const { return exact_duplicates + back_to_back_twins; }
};

struct FilteredTriangles {
    std::vector<SoupTriangle> kept;
    std::vector<TriangleFate> fate;  // per MDL triangle
    TriangleFilterCounts counts;
};

// Of a set of duplicates the first in file order is kept (for twins: the file's own choice of
// which side comes first; orientation.h may still flip it to agree with its neighbours).
FilteredTriangles filter_triangles(const AliasSource& source, const VertexWeld& weld);

}  // namespace nq::npr::adjacency

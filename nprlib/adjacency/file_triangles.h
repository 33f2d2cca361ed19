// The file's own triangles and how their sides meet, for what does not need the repaired
// mesh: the paper's back-face lines (Mohr et al. 2002 draw every back-facing triangle's
// edges; a side between two triangles that both face away lies on the far side of the model
// and is left out) and skin seams (a seam duplicates vertices in the file; welded positions
// tell that they are one).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "adjacency/alias_source.h"
#include "adjacency/mesh_builder.h"

namespace nq::npr::adjacency {

using FileTriangle = std::array<uint32_t, 3>;  // MDL vertices

struct FileTriangles {
    // The file's usable triangles (indices in range, three different corners) in file order,
    // counter-clockwise seen from outside (the reverse of the file's winding).
    std::vector<FileTriangle> triangles;
    // Per triangle side k (from corner k to k + 1): the one triangle running that side the
    // other way round at the same welded positions, or -1 when there is none or the side has
    // more than two triangles.
    std::vector<std::array<int32_t, 3>> twins;
    // Per MDL vertex: the lowest-numbered MDL vertex at its welded position, itself where
    // there is no other (or no face of the mesh uses it).
    std::vector<uint32_t> seam_representatives;
};

FileTriangles describe_file_triangles(const AliasSource& source, const BuiltMesh& built);

}  // namespace nq::npr::adjacency

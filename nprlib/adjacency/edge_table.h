// Per-edge adjacency of a built mesh, computed once per model:
//   edges    each edge's two mesh vertices, its one or two faces and their far corners (the
//            mesh's own numbering: for pose geometry, checks and reports);
//   records  the same edges in MDL vertex indices, the form a renderer tests on a blended
//            pose every frame (feature_edges.h): the technical style draws exactly these.
// MDL indices index a vertex buffer laid out like the file's vertices (texture coordinates
// included); faces wind counter-clockwise seen from outside (GL's default front face; Quake's
// files store the opposite winding).
#pragma once

#include <cstdint>
#include <vector>

#include "adjacency/mesh_builder.h"

namespace nq::npr::adjacency {

struct MeshEdge {
    uint32_t v0 = 0, v1 = 0;     // mesh vertices; face0 runs v0 -> v1, face1 (if any) v1 -> v0
    uint32_t face0 = 0;          // always a face
    uint32_t face1 = kNone;      // kNone on a boundary edge
    uint32_t opposite0 = 0;      // mesh vertex of face0 not on the edge
    uint32_t opposite1 = kNone;  // mesh vertex of face1 not on the edge
    bool boundary() const { return face1 == kNone; }
};

// One edge in MDL vertex indices: face0 is (v0, v1, third), its neighbour (v1, v0, far), both
// counter-clockwise seen from outside. On an open border there is no neighbour and far is
// face0's own third corner.
struct EdgeRecord {
    uint32_t third = 0, v0 = 0, v1 = 0, far = 0;
    bool border() const { return far == third; }
};

struct EdgeTable {
    std::vector<MeshEdge> edges;
    std::vector<EdgeRecord> records;  // records[e] is edges[e]

    uint32_t boundary_edges() const;
};

EdgeTable build_edge_table(const BuiltMesh& built);

}  // namespace nq::npr::adjacency

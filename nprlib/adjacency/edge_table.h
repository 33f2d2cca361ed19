// Per-edge adjacency of a built mesh, computed once per model, in forms a renderer can use
// directly:
//   edges               each edge's two vertices and its one or two faces;
//   triangles_adjacency 6 MDL vertex indices per face for GL_TRIANGLES_ADJACENCY;
//   edge_lines          2 MDL vertex indices per edge for GL_LINES (draw any subset);
//   face_edges          each face's three edges.
// GPU indices are MDL vertex indices, so they index a vertex buffer laid out like the file's
// vertices (texture coordinates included); faces wind counter-clockwise seen from outside
// (GL's default front face; Quake's files store the opposite winding).
#pragma once

#include <array>
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

struct EdgeTable {
    std::vector<MeshEdge> edges;
    // Per face: corner0, across edge 0-1, corner1, across edge 1-2, corner2, across edge 2-0.
    // On a boundary edge the "across" vertex is the face's own third corner, so a geometry
    // shader sees the face itself reversed there and always finds the edge on the outline.
    std::vector<uint32_t> triangles_adjacency;
    std::vector<uint32_t> edge_lines;                 // per edge: MDL vertices at v0 and v1
    std::vector<std::array<uint32_t, 3>> face_edges;  // edge k joins corners k and k + 1

    uint32_t boundary_edges() const;
};

EdgeTable build_edge_table(const BuiltMesh& built);

}  // namespace nq::npr::adjacency

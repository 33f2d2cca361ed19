// The welded, filtered, oriented triangles as one OpenMesh half-edge mesh, vertices split
// wherever the soup is not manifold, so that every edge has one or two faces and every vertex
// one fan. The mesh's topology is shared by every pose; positions come from the MDL's poses.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "adjacency/alias_source.h"
#include "adjacency/mesh_types.h"
#include "adjacency/orientation.h"
#include "adjacency/triangle_filter.h"
#include "adjacency/weld.h"

namespace nq::npr::adjacency {

// Why vertices were split (each is counted once per face or vertex concerned).
struct SplitCounts {
    uint32_t complex_edge_faces = 0;    // faces placed on a new vertex copy: an edge was full
    uint32_t complex_vertex_faces = 0;  // ... a corner was already surrounded by faces
    uint32_t deferred_faces = 0;        // refused while building; added after the fan split
    uint32_t island_faces = 0;          // refused even then: on three fresh copies (OpenMesh's way)
    uint32_t fan_splits = 0;            // copies for vertices left joining separate fans
    uint32_t new_vertices = 0;          // mesh vertices beyond one per welded vertex in use
};

struct BuiltMesh {
    TriMesh mesh;  // points: pose 0 (the origin for a model without poses)
    // Per mesh face (OpenMesh's face index), corners counter-clockwise seen from outside,
    // i.e. the reverse of Quake's stored winding unless the face was flipped:
    std::vector<std::array<uint32_t, 3>> face_vertices;  // mesh vertices
    std::vector<std::array<uint32_t, 3>> face_corners;   // MDL vertices (texture coordinates)
    std::vector<uint32_t> face_triangle;                 // the MDL triangle
    std::vector<uint8_t> face_flipped;                   // 1: orientation.h reversed it
    std::vector<uint32_t> vertex_welded;                 // per mesh vertex: its welded vertex
    std::vector<uint32_t> vertex_mdl;                    // per mesh vertex: an MDL vertex there
    SplitCounts splits;
};

BuiltMesh build_mesh(const AliasSource& source, const VertexWeld& weld,
                     std::span<const SoupTriangle> soup, const OrientationPlan& plan);

}  // namespace nq::npr::adjacency

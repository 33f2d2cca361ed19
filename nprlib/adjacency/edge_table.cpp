#include "adjacency/edge_table.h"

namespace nq::npr::adjacency {

namespace {

OpenMesh::VertexHandle handle(uint32_t v) {
    return OpenMesh::VertexHandle(static_cast<int>(v));
}

// The MDL vertex at mesh vertex `v` in face `f` (the file's texture coordinates).
uint32_t corner_mdl_vertex(const BuiltMesh& built, uint32_t f, uint32_t v) {
    for (int k = 0; k < 3; ++k) {
        if (built.face_vertices[f][k] == v) return built.face_corners[f][k];
    }
    return built.vertex_mdl[v];  // not reached for a consistent mesh (mesh_checks)
}

MeshEdge describe_edge(const TriMesh& mesh, OpenMesh::EdgeHandle e) {
    auto h = mesh.halfedge_handle(e, 0);
    if (mesh.is_boundary(h)) h = mesh.opposite_halfedge_handle(h);
    const auto o = mesh.opposite_halfedge_handle(h);
    MeshEdge edge;
    edge.v0 = uint32_t(mesh.from_vertex_handle(h).idx());
    edge.v1 = uint32_t(mesh.to_vertex_handle(h).idx());
    edge.face0 = uint32_t(mesh.face_handle(h).idx());
    edge.opposite0 = uint32_t(mesh.to_vertex_handle(mesh.next_halfedge_handle(h)).idx());
    if (!mesh.is_boundary(o)) {
        edge.face1 = uint32_t(mesh.face_handle(o).idx());
        edge.opposite1 = uint32_t(mesh.to_vertex_handle(mesh.next_halfedge_handle(o)).idx());
    }
    return edge;
}

void add_face_adjacency(const BuiltMesh& built, uint32_t f, EdgeTable& table) {
    const TriMesh& mesh = built.mesh;
    const auto& v = built.face_vertices[f];
    for (int k = 0; k < 3; ++k) {
        table.triangles_adjacency.push_back(built.face_corners[f][k]);
        const auto h = mesh.find_halfedge(handle(v[k]), handle(v[(k + 1) % 3]));
        const auto o = mesh.opposite_halfedge_handle(h);
        table.face_edges[f][k] = uint32_t(mesh.edge_handle(h).idx());
        if (mesh.is_boundary(o)) {
            table.triangles_adjacency.push_back(built.face_corners[f][(k + 2) % 3]);
        } else {
            const uint32_t g = uint32_t(mesh.face_handle(o).idx());
            const uint32_t across =
                uint32_t(mesh.to_vertex_handle(mesh.next_halfedge_handle(o)).idx());
            table.triangles_adjacency.push_back(corner_mdl_vertex(built, g, across));
        }
    }
}

}  // namespace

uint32_t EdgeTable::boundary_edges() const {
    uint32_t n = 0;
    for (const MeshEdge& e : edges) n += e.boundary();
    return n;
}

EdgeTable build_edge_table(const BuiltMesh& built) {
    const TriMesh& mesh = built.mesh;
    EdgeTable table;
    table.edges.reserve(mesh.n_edges());
    table.edge_lines.reserve(mesh.n_edges() * 2);
    for (const auto e : mesh.edges()) {
        const MeshEdge edge = describe_edge(mesh, e);
        table.edges.push_back(edge);
        table.edge_lines.push_back(corner_mdl_vertex(built, edge.face0, edge.v0));
        table.edge_lines.push_back(corner_mdl_vertex(built, edge.face0, edge.v1));
    }
    table.face_edges.resize(built.face_vertices.size());
    table.triangles_adjacency.reserve(built.face_vertices.size() * 6);
    for (uint32_t f = 0; f < built.face_vertices.size(); ++f) add_face_adjacency(built, f, table);
    return table;
}

}  // namespace nq::npr::adjacency

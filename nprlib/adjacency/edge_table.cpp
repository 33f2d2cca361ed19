#include "adjacency/edge_table.h"

namespace nq::npr::adjacency {

namespace {

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

EdgeRecord record_of(const BuiltMesh& built, const MeshEdge& edge) {
    EdgeRecord record;
    record.third = corner_mdl_vertex(built, edge.face0, edge.opposite0);
    record.v0 = corner_mdl_vertex(built, edge.face0, edge.v0);
    record.v1 = corner_mdl_vertex(built, edge.face0, edge.v1);
    record.far =
        edge.boundary() ? record.third : corner_mdl_vertex(built, edge.face1, edge.opposite1);
    return record;
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
    table.records.reserve(mesh.n_edges());
    for (const auto e : mesh.edges()) {
        table.edges.push_back(describe_edge(mesh, e));
        table.records.push_back(record_of(built, table.edges.back()));
    }
    return table;
}

}  // namespace nq::npr::adjacency

#include "adjacency/mesh_checks.h"

#include "adjacency/edge_census.h"

namespace nq::npr::adjacency {

namespace {

class Problems {
  public:
    void add(std::string line) {
        if (lines_.size() < kMaxProblems) lines_.push_back(std::move(line));
        ++count_;
    }
    std::vector<std::string> take() {
        if (count_ > lines_.size()) {
            lines_.push_back(std::to_string(count_ - lines_.size()) + " more problems");
        }
        return std::move(lines_);
    }

  private:
    std::vector<std::string> lines_;
    size_t count_ = 0;
};

void check_halfedges(const TriMesh& mesh, Problems& problems) {
    for (const auto h : mesh.halfedges()) {
        const std::string name = "halfedge " + std::to_string(h.idx());
        const auto next = mesh.next_halfedge_handle(h);
        if (mesh.opposite_halfedge_handle(mesh.opposite_halfedge_handle(h)) != h) {
            problems.add(name + ": opposite of opposite is not itself");
        }
        if (!next.is_valid() || mesh.prev_halfedge_handle(next) != h) {
            problems.add(name + ": next/prev do not agree");
        } else if (mesh.from_vertex_handle(next) != mesh.to_vertex_handle(h)) {
            problems.add(name + ": next does not start where it ends");
        } else if (mesh.face_handle(next) != mesh.face_handle(h)) {
            problems.add(name + ": next lies on another face");
        }
    }
}

void check_edges_and_vertices(const TriMesh& mesh, Problems& problems) {
    for (const auto e : mesh.edges()) {
        if (mesh.is_boundary(mesh.halfedge_handle(e, 0)) &&
            mesh.is_boundary(mesh.halfedge_handle(e, 1))) {
            problems.add("edge " + std::to_string(e.idx()) + " has no face");
        }
    }
    for (const auto v : mesh.vertices()) {
        if (mesh.is_isolated(v)) problems.add("vertex " + std::to_string(v.idx()) + " isolated");
        if (!mesh.is_manifold(v)) {
            problems.add("vertex " + std::to_string(v.idx()) + " is not manifold");
        }
    }
}

// The face's halfedge loop is a triangle through face_vertices[f] in that cyclic order.
void check_faces(const BuiltMesh& built, Problems& problems) {
    const TriMesh& mesh = built.mesh;
    if (mesh.n_faces() != built.face_vertices.size()) {
        problems.add("face table has " + std::to_string(built.face_vertices.size()) +
                     " faces, the mesh " + std::to_string(mesh.n_faces()));
        return;
    }
    for (const auto f : mesh.faces()) {
        const auto& expected = built.face_vertices[f.idx()];
        const auto h0 = mesh.halfedge_handle(f);
        auto h = h0;
        int start = -1, n = 0;
        for (int k = 0; k < 3; ++k) {
            if (expected[k] == uint32_t(mesh.from_vertex_handle(h0).idx())) start = k;
        }
        bool matches = start >= 0;
        do {
            if (matches &&
                uint32_t(mesh.from_vertex_handle(h).idx()) != expected[(start + n) % 3]) {
                matches = false;
            }
            h = mesh.next_halfedge_handle(h);
        } while (h != h0 && ++n < 4);
        if (n != 2 || !matches) {
            problems.add("face " + std::to_string(f.idx()) + " does not match its face table row");
        }
    }
}

}  // namespace

std::vector<std::string> check_mesh(const BuiltMesh& built) {
    Problems problems;
    check_halfedges(built.mesh, problems);
    check_edges_and_vertices(built.mesh, problems);
    check_faces(built, problems);
    const EdgeCensus census = census_of_indexed_triangles(built.face_vertices);
    if (census.non_manifold > 0) {
        problems.add(std::to_string(census.non_manifold) + " edges used by three or more faces");
    }
    if (census.boundary + census.manifold != census.edges || census.edges != built.mesh.n_edges()) {
        problems.add("face table edges differ from the mesh's");
    }
    if (census.consistent != census.manifold) {
        problems.add(std::to_string(census.manifold - census.consistent) +
                     " interior edges traversed twice in the same direction");
    }
    return problems.take();
}

}  // namespace nq::npr::adjacency

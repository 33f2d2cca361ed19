#include "adjacency/mesh_builder.h"

#include "adjacency/face_placement.h"
#include "adjacency/fan_split.h"
#include "adjacency/quiet_openmesh.h"

namespace nq::npr::adjacency {

namespace {

OpenMesh::VertexHandle handle(uint32_t v) {
    return OpenMesh::VertexHandle(static_cast<int>(v));
}

// Mesh faces are counter-clockwise from outside; Quake stores them clockwise.
constexpr std::array<int, 3> kReversed{0, 2, 1};
constexpr std::array<int, 3> kAsStored{0, 1, 2};

class Builder {
  public:
    Builder(const AliasSource& source, const VertexWeld& weld, BuiltMesh& out)
        : source_(source), weld_(weld), out_(out), copies_(weld.num_classes()) {}

    void add(const SoupTriangle& t, bool flipped) {
        const std::array<int, 3>& order = flipped ? kAsStored : kReversed;
        std::array<uint32_t, 3> welded, corners;
        for (int k = 0; k < 3; ++k) {
            welded[k] = t.welded[order[k]];
            corners[k] = t.mdl_vertices[order[k]];
        }
        const std::array<uint32_t, 3> v = place(welded);
        // OpenMesh can refuse a placement the pre-check accepts (it cannot close a fan at a
        // vertex whose other fan came first). The face keeps its place in the face table and
        // is added when the mesh is rebuilt after the fan split, which separates those fans.
        if (!try_add_face(v)) ++out_.splits.deferred_faces;
        out_.face_vertices.push_back(v);
        out_.face_corners.push_back(corners);
        out_.face_triangle.push_back(t.mdl_triangle);
        out_.face_flipped.push_back(flipped ? 1 : 0);
    }

    bool needs_rebuild() const { return out_.splits.deferred_faces > 0; }

  private:
    std::array<uint32_t, 3> place(const std::array<uint32_t, 3>& welded) {
        const Placement p = choose_placement(
            out_.mesh, {&copies_[welded[0]], &copies_[welded[1]], &copies_[welded[2]]});
        if (p.splits > 0) count_split_cause(welded);
        std::array<uint32_t, 3> v = p.vertices;
        for (int k = 0; k < 3; ++k) {
            if (v[k] == kNone) v[k] = new_copy(welded[k]);
        }
        return v;
    }

    // Judged on the placement a plain weld would have used: every corner's first copy.
    void count_split_cause(const std::array<uint32_t, 3>& welded) {
        std::array<uint32_t, 3> plain;
        for (int k = 0; k < 3; ++k) {
            plain[k] = copies_[welded[k]].empty() ? kNone : copies_[welded[k]].front();
        }
        if (refusal_reason(out_.mesh, plain) == Refusal::complex_edge) {
            ++out_.splits.complex_edge_faces;
        } else {
            ++out_.splits.complex_vertex_faces;
        }
    }

    uint32_t new_copy(uint32_t welded) {
        const uint32_t mdl = weld_.representative[welded];
        TriMesh::Point point(0.0f, 0.0f, 0.0f);
        if (source_.num_poses() > 0) {
            const glm::vec3 p = source_.position(0, mdl);
            point = TriMesh::Point(p.x, p.y, p.z);
        }
        const uint32_t v = static_cast<uint32_t>(out_.mesh.add_vertex(point).idx());
        copies_[welded].push_back(v);
        out_.vertex_welded.push_back(welded);
        out_.vertex_mdl.push_back(mdl);
        return v;
    }

    bool try_add_face(const std::array<uint32_t, 3>& v) {
        return out_.mesh.add_face(handle(v[0]), handle(v[1]), handle(v[2])).is_valid();
    }

    const AliasSource& source_;
    const VertexWeld& weld_;
    BuiltMesh& out_;
    std::vector<std::vector<uint32_t>> copies_;  // per welded vertex: its mesh vertices
};

// Vertex v of a rebuilt mesh is vertex origin[v] of the current one.
struct Renumbering {
    std::vector<uint32_t> origin;
    std::vector<std::array<uint32_t, 3>> faces;
};

// Drops vertices no face uses (left behind when a face had to become an island).
void drop_unused_vertices(Renumbering& r) {
    std::vector<uint32_t> renamed(r.origin.size(), kNone);
    std::vector<uint32_t> origin;
    for (auto& face : r.faces) {
        for (uint32_t& v : face) {
            if (renamed[v] == kNone) {
                renamed[v] = static_cast<uint32_t>(origin.size());
                origin.push_back(r.origin[v]);
            }
            v = renamed[v];
        }
    }
    r.origin = std::move(origin);
}

// Rebuilds the mesh from scratch on a new numbering, faces in the same order. A face OpenMesh
// still refuses goes on three fresh copies of its vertices, as OpenMesh's own importer does.
// Returns how many faces that happened to.
uint32_t rebuild(BuiltMesh& built, const Renumbering& r) {
    TriMesh mesh;
    std::vector<uint32_t> welded, mdl;
    // The point by value: a reference into the mesh would dangle when adding reallocates.
    auto add_vertex = [&](TriMesh::Point point, uint32_t w, uint32_t m) {
        welded.push_back(w);
        mdl.push_back(m);
        return static_cast<uint32_t>(mesh.add_vertex(point).idx());
    };
    for (uint32_t old : r.origin) {
        add_vertex(built.mesh.point(handle(old)), built.vertex_welded[old], built.vertex_mdl[old]);
    }
    uint32_t islands = 0;
    for (size_t f = 0; f < r.faces.size(); ++f) {
        std::array<uint32_t, 3> v = r.faces[f];
        if (!mesh.add_face(handle(v[0]), handle(v[1]), handle(v[2])).is_valid()) {
            ++islands;
            for (uint32_t& corner : v) {
                corner = add_vertex(mesh.point(handle(corner)), welded[corner], mdl[corner]);
            }
            mesh.add_face(handle(v[0]), handle(v[1]), handle(v[2]));
        }
        built.face_vertices[f] = v;
    }
    built.mesh = std::move(mesh);
    built.vertex_welded = std::move(welded);
    built.vertex_mdl = std::move(mdl);
    return islands;
}

// Gives every fan of faces around a vertex its own vertex, then rebuilds. Turning a face into
// an island can leave a vertex with two fans again (the island was the bridge), so this repeats
// until no face had to be islanded (an island is never refused again, so it settles at once in
// practice; the bound only guards against a surprise, which mesh_checks would then report).
void split_fans_and_rebuild(BuiltMesh& built, bool faces_missing) {
    constexpr int kMaxRounds = 8;
    for (int round = 0; round < kMaxRounds; ++round) {
        const FanSplit split =
            split_vertex_fans(built.face_vertices, static_cast<uint32_t>(built.mesh.n_vertices()));
        if (split.extra_vertices == 0 && !faces_missing) return;
        built.splits.fan_splits += split.extra_vertices;
        Renumbering r{split.origin, split.faces};
        drop_unused_vertices(r);
        const uint32_t islands = rebuild(built, r);
        built.splits.island_faces += islands;
        faces_missing = islands > 0;  // their old vertices may be unused now
    }
}

uint32_t welded_vertices_in_use(const BuiltMesh& built, uint32_t num_classes) {
    std::vector<uint8_t> used(num_classes, 0);
    uint32_t count = 0;
    for (uint32_t w : built.vertex_welded) {
        count += used[w] == 0;
        used[w] = 1;
    }
    return count;
}

}  // namespace

BuiltMesh build_mesh(const AliasSource& source, const VertexWeld& weld,
                     std::span<const SoupTriangle> soup, const OrientationPlan& plan) {
    BuiltMesh built;
    const QuietOpenMesh quiet;
    Builder builder(source, weld, built);
    for (uint32_t t : plan.order) builder.add(soup[t], plan.flipped[t] != 0);
    split_fans_and_rebuild(built, builder.needs_rebuild());
    built.splits.new_vertices = static_cast<uint32_t>(built.mesh.n_vertices()) -
                                welded_vertices_in_use(built, weld.num_classes());
    return built;
}

}  // namespace nq::npr::adjacency

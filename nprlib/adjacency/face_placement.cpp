#include "adjacency/face_placement.h"

#include <algorithm>
#include <tuple>

namespace nq::npr::adjacency {

namespace {

// Copies tried per corner (plus "new"): enough for every split pattern seen in real models,
// and a bound on the 5^3 placements enumerated per face.
constexpr size_t kMaxCopiesTried = 4;

OpenMesh::VertexHandle handle(uint32_t v) {
    return OpenMesh::VertexHandle(static_cast<int>(v));
}

// Edges of the face that already exist (each then gets this face on its free side).
uint32_t joined_edges(const TriMesh& mesh, const std::array<uint32_t, 3>& v) {
    uint32_t joined = 0;
    for (int k = 0; k < 3; ++k) {
        const uint32_t a = v[k], b = v[(k + 1) % 3];
        if (a != kNone && b != kNone && mesh.find_halfedge(handle(a), handle(b)).is_valid()) {
            ++joined;
        }
    }
    return joined;
}

}  // namespace

Refusal refusal_reason(const TriMesh& mesh, const std::array<uint32_t, 3>& v) {
    for (int k = 0; k < 3; ++k) {
        const uint32_t a = v[k], b = v[(k + 1) % 3];
        if (a == kNone || b == kNone) continue;
        const auto h = mesh.find_halfedge(handle(a), handle(b));
        if (h.is_valid() && !mesh.is_boundary(h)) return Refusal::complex_edge;
    }
    for (uint32_t a : v) {
        // is_boundary is true for an isolated vertex too: a free gap to put the face in.
        if (a != kNone && !mesh.is_boundary(handle(a))) return Refusal::complex_vertex;
    }
    return Refusal::none;
}

Placement choose_placement(const TriMesh& mesh,
                           const std::array<const std::vector<uint32_t>*, 3>& copies) {
    std::array<size_t, 3> options{};
    for (int k = 0; k < 3; ++k) options[k] = std::min(copies[k]->size(), kMaxCopiesTried) + 1;
    Placement best;
    std::tuple<uint32_t, int, uint32_t> best_score{0, 0, 0};
    std::array<size_t, 3> pick{};
    for (pick[0] = 0; pick[0] < options[0]; ++pick[0]) {
        for (pick[1] = 0; pick[1] < options[1]; ++pick[1]) {
            for (pick[2] = 0; pick[2] < options[2]; ++pick[2]) {
                Placement p;
                uint32_t existing = 0;
                for (int k = 0; k < 3; ++k) {
                    const bool fresh = pick[k] + 1 == options[k];
                    p.vertices[k] = fresh ? kNone : (*copies[k])[pick[k]];
                    existing += !fresh;
                    p.splits += fresh && !copies[k]->empty();
                }
                if (refusal_reason(mesh, p.vertices) != Refusal::none) continue;
                const std::tuple<uint32_t, int, uint32_t> score{joined_edges(mesh, p.vertices),
                                                                -int(p.splits), existing};
                if (!best.found || score > best_score) {
                    best = p;
                    best.found = true;
                    best_score = score;
                }
            }
        }
    }
    return best;
}

}  // namespace nq::npr::adjacency

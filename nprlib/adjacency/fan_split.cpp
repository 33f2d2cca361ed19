#include "adjacency/fan_split.h"

#include <numeric>

namespace nq::npr::adjacency {

namespace {

constexpr uint32_t kNoCopy = UINT32_MAX;

// Faces around each vertex: entries [start[v], start[v + 1]) of `face`.
struct Incidence {
    std::vector<uint32_t> start, face;
};

Incidence incidence(std::span<const std::array<uint32_t, 3>> faces, uint32_t num_vertices) {
    Incidence in;
    in.start.assign(num_vertices + 1, 0);
    for (const auto& f : faces) {
        for (uint32_t v : f) ++in.start[v + 1];
    }
    for (uint32_t v = 0; v < num_vertices; ++v) in.start[v + 1] += in.start[v];
    in.face.resize(in.start.back());
    std::vector<uint32_t> fill(in.start.begin(), in.start.end() - 1);
    for (uint32_t i = 0; i < faces.size(); ++i) {
        for (uint32_t v : faces[i]) in.face[fill[v]++] = i;
    }
    return in;
}

uint32_t find_root(std::vector<uint32_t>& parent, uint32_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
}

// Fan of each face around `v` (as the root local index), faces given by `around`.
std::vector<uint32_t> fans_around(uint32_t v, std::span<const uint32_t> around,
                                  std::span<const std::array<uint32_t, 3>> faces) {
    std::vector<uint32_t> parent(around.size());
    std::iota(parent.begin(), parent.end(), 0u);
    std::vector<std::pair<uint32_t, uint32_t>> first_face_at;  // neighbour vertex -> local face
    for (uint32_t i = 0; i < around.size(); ++i) {
        for (uint32_t x : faces[around[i]]) {
            if (x == v) continue;
            bool seen = false;
            for (const auto& [vertex, local] : first_face_at) {
                if (vertex != x) continue;
                parent[find_root(parent, i)] = find_root(parent, local);
                seen = true;
            }
            if (!seen) first_face_at.emplace_back(x, i);
        }
    }
    for (uint32_t i = 0; i < around.size(); ++i) parent[i] = find_root(parent, i);
    return parent;
}

}  // namespace

FanSplit split_vertex_fans(std::span<const std::array<uint32_t, 3>> faces, uint32_t num_vertices) {
    FanSplit out;
    out.faces.assign(faces.begin(), faces.end());
    out.origin.resize(num_vertices);
    std::iota(out.origin.begin(), out.origin.end(), 0u);
    const Incidence in = incidence(faces, num_vertices);
    for (uint32_t v = 0; v < num_vertices; ++v) {
        const std::span<const uint32_t> around(in.face.data() + in.start[v],
                                               in.start[v + 1] - in.start[v]);
        if (around.size() < 2) continue;
        const std::vector<uint32_t> fan = fans_around(v, around, faces);
        std::vector<std::pair<uint32_t, uint32_t>> copy_of_fan;  // fan root -> vertex
        for (uint32_t i = 0; i < around.size(); ++i) {
            uint32_t target = kNoCopy;
            for (const auto& [root, vertex] : copy_of_fan) {
                if (root == fan[i]) target = vertex;
            }
            if (target == kNoCopy) {
                // The fan of the first face keeps the vertex; each other fan gets a copy.
                target = copy_of_fan.empty() ? v : num_vertices + out.extra_vertices++;
                if (target != v) out.origin.push_back(v);
                copy_of_fan.emplace_back(fan[i], target);
            }
            for (uint32_t& corner : out.faces[around[i]]) {
                if (corner == v) corner = target;
            }
        }
    }
    return out;
}

}  // namespace nq::npr::adjacency

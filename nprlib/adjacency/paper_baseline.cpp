#include "adjacency/paper_baseline.h"

#include <array>
#include <chrono>
#include <cstring>
#include <unordered_map>

namespace nq::npr::adjacency {

namespace {

// An undirected edge by its endpoint positions, lexicographically smaller endpoint first.
struct PositionEdge {
    std::array<float, 6> ends{};
    bool operator==(const PositionEdge& o) const { return ends == o.ends; }
};

struct PositionEdgeHash {
    size_t operator()(const PositionEdge& e) const {
        uint64_t h = 1469598103934665603ull;
        for (float f : e.ends) {
            uint32_t bits;
            std::memcpy(&bits, &f, sizeof bits);
            h = (h ^ bits) * 1099511628211ull;
        }
        return static_cast<size_t>(h);
    }
};

struct Uses {
    uint32_t forward = 0, backward = 0;
};

std::array<float, 3> exact_position(const AliasSource& source, uint32_t pose, uint32_t v) {
    const glm::vec3 p = source.position(pose, v);
    return {p.x + 0.0f, p.y + 0.0f, p.z + 0.0f};  // + 0 turns -0 into +0, which hashes alike
}

void hash_edge(const std::array<float, 3>& a, const std::array<float, 3>& b,
               std::unordered_map<PositionEdge, Uses, PositionEdgeHash>& table) {
    const bool backward = b < a;
    const auto& lo = backward ? b : a;
    const auto& hi = backward ? a : b;
    PositionEdge key;
    std::memcpy(key.ends.data(), lo.data(), sizeof lo);
    std::memcpy(key.ends.data() + 3, hi.data(), sizeof hi);
    Uses& uses = table[key];
    ++(backward ? uses.backward : uses.forward);
}

}  // namespace

EdgeCensus hash_edges_in_pose(const AliasSource& source, uint32_t pose) {
    std::unordered_map<PositionEdge, Uses, PositionEdgeHash> table;
    table.reserve(size_t(source.num_triangles()) * 2);
    for (uint32_t t = 0; t < source.num_triangles(); ++t) {
        const AliasTriangle tri = source.triangle(t);
        if (!source.vertex_in_range(tri.vertices[0]) || !source.vertex_in_range(tri.vertices[1]) ||
            !source.vertex_in_range(tri.vertices[2])) {
            continue;
        }
        std::array<std::array<float, 3>, 3> p;
        for (int k = 0; k < 3; ++k) p[k] = exact_position(source, pose, uint32_t(tri.vertices[k]));
        for (int k = 0; k < 3; ++k) hash_edge(p[k], p[(k + 1) % 3], table);
    }
    EdgeCensus census;
    for (const auto& [edge, uses] : table) {
        const bool zero_length = std::memcmp(edge.ends.data(), edge.ends.data() + 3, 12) == 0;
        census.add_edge(uses.forward, uses.backward, zero_length);
    }
    return census;
}

BaselineReport run_paper_baseline(const AliasSource& source) {
    BaselineReport report;
    report.poses = source.num_poses();
    const auto start = std::chrono::steady_clock::now();
    for (uint32_t pose = 0; pose < source.num_poses(); ++pose) {
        const EdgeCensus census = hash_edges_in_pose(source, pose);
        if (pose == 0) {
            report.first_pose = report.worst_pose = census;
        } else {
            report.poses_unlike_first += !(census == report.first_pose);
            if (census.consistent_share() < report.worst_pose.consistent_share()) {
                report.worst_pose = census;
                report.worst_pose_index = pose;
            }
        }
    }
    report.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report;
}

}  // namespace nq::npr::adjacency

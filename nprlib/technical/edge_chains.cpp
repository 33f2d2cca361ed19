#include "technical/edge_chains.h"

#include <algorithm>

#include <glm/geometric.hpp>

namespace nq::npr::technical {
namespace {

// A run never spans more vertices than this: bounds the work of a long straight chain.
constexpr size_t kMaxRunPoints = 32;
constexpr uint32_t kKinds = 4;  // EdgeKind's values

uint32_t end_vertex(const FoundEdge& edge, uint32_t end) {
    return end == 0 ? edge.v0 : edge.v1;
}

float distance_to_segment(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b) {
    const glm::vec3 ab = b - a;
    const float length2 = glm::dot(ab, ab);
    const float t = length2 > 0.0f ? std::clamp(glm::dot(p - a, ab) / length2, 0.0f, 1.0f) : 0.0f;
    return glm::length(a + t * ab - p);
}

}  // namespace

void EdgeChains::simplify(std::vector<FoundEdge>& edges, std::span<const uint32_t> representative,
                          const glm::vec3* view, const ChainTolerance& tolerance) {
    if (edges.size() < 2 || !view || tolerance.pixels <= 0.0f ||
        tolerance.units_per_pixel_per_depth <= 0.0f) {
        return;
    }
    link_ends(edges, representative);
    visited_.assign(edges.size(), 0);
    out_.clear();
    // Open chains from an end that continues nowhere first; what is left are closed loops.
    for (const bool loops : {false, true}) {
        for (uint32_t e = 0; e < edges.size(); ++e) {
            if (visited_[e]) continue;
            for (uint32_t end = 0; end < 2; ++end) {
                if (!loops && link_[e * 2 + end] >= 0) continue;
                walk(edges, e, end);
                emit_runs(edges[e].kind, view, tolerance);
                break;
            }
        }
    }
    edges.swap(out_);
}

EdgeChains::Meeting* EdgeChains::meeting(const FoundEdge& edge, uint32_t vertex,
                                         std::span<const uint32_t> representative) {
    if (vertex >= representative.size()) return nullptr;
    const size_t index = size_t(representative[vertex]) * kKinds + static_cast<uint32_t>(edge.kind);
    return index < meetings_.size() ? &meetings_[index] : nullptr;
}

// Ends of one kind at one welded position: exactly two (of different edges) continue into
// each other.
void EdgeChains::link_ends(const std::vector<FoundEdge>& edges,
                           std::span<const uint32_t> representative) {
    if (meetings_.size() < representative.size() * kKinds) {
        meetings_.resize(representative.size() * kKinds);
    }
    if (++stamp_ == 0) {  // wrapped: old stamps could match again
        std::fill(meetings_.begin(), meetings_.end(), Meeting{});
        stamp_ = 1;
    }
    for (uint32_t slot = 0; slot < edges.size() * 2; ++slot) {
        Meeting* m =
            meeting(edges[slot / 2], end_vertex(edges[slot / 2], slot % 2), representative);
        if (!m) continue;
        if (m->stamp != stamp_) *m = {stamp_, 0, slot, slot};
        if (m->count++ == 1) m->second = slot;
    }
    link_.assign(edges.size() * 2, -1);
    for (uint32_t slot = 0; slot < edges.size() * 2; ++slot) {
        const Meeting* m =
            meeting(edges[slot / 2], end_vertex(edges[slot / 2], slot % 2), representative);
        if (!m || m->count != 2 || m->first != slot || m->first / 2 == m->second / 2) continue;
        link_[m->first] = static_cast<int32_t>(m->second);
        link_[m->second] = static_cast<int32_t>(m->first);
    }
}

// The chain from `edge`, entered at `end`, as a list of vertices; a closed loop ends where it
// started.
void EdgeChains::walk(const std::vector<FoundEdge>& edges, uint32_t edge, uint32_t end) {
    points_.clear();
    points_.push_back(end_vertex(edges[edge], end));
    for (;;) {
        visited_[edge] = 1;
        const uint32_t exit = 1 - end;
        points_.push_back(end_vertex(edges[edge], exit));
        const int32_t next = link_[edge * 2 + exit];
        if (next < 0 || visited_[static_cast<uint32_t>(next) / 2]) break;
        edge = static_cast<uint32_t>(next) / 2;
        end = static_cast<uint32_t>(next) % 2;
    }
}

void EdgeChains::emit_runs(EdgeKind kind, const glm::vec3* view, const ChainTolerance& tolerance) {
    for (size_t from = 0; from + 1 < points_.size();) {
        size_t to = from + 1;
        while (to + 1 < points_.size() && to + 1 - from < kMaxRunPoints &&
               straight(from, to + 1, view, tolerance)) {
            ++to;
        }
        out_.push_back({points_[from], points_[to], kind});
        from = to;
    }
}

bool EdgeChains::straight(size_t from, size_t to, const glm::vec3* view,
                          const ChainTolerance& tolerance) const {
    const glm::vec3& a = view[points_[from]];
    const glm::vec3& b = view[points_[to]];
    const float per_depth = tolerance.pixels * tolerance.units_per_pixel_per_depth;
    if (a.z >= 0.0f || b.z >= 0.0f) return false;  // the near plane's clipping stays exact
    for (size_t m = from + 1; m < to; ++m) {
        const glm::vec3& p = view[points_[m]];
        if (p.z >= 0.0f) return false;
        if (distance_to_segment(p, a, b) > per_depth * -p.z) return false;
    }
    return true;
}

}  // namespace nq::npr::technical

#include "adjacency/edge_census.h"

#include <algorithm>
#include <compare>
#include <vector>

namespace nq::npr::adjacency {

void EdgeCensus::add_edge(uint32_t forward_uses, uint32_t backward_uses, bool is_zero_length) {
    ++edges;
    const uint32_t uses = forward_uses + backward_uses;
    if (is_zero_length) {
        ++zero_length;
    } else if (uses == 1) {
        ++boundary;
    } else if (uses == 2) {
        ++manifold;
        if (forward_uses == 1) ++consistent;
    } else {
        ++non_manifold;
    }
}

namespace {

struct EdgeUse {
    uint32_t low, high;
    bool backward;  // traversed from high to low
    auto operator<=>(const EdgeUse&) const = default;
};

}  // namespace

EdgeCensus census_of_indexed_triangles(std::span<const std::array<uint32_t, 3>> triangles) {
    // Sorted so that each edge's uses are adjacent.
    std::vector<EdgeUse> uses;
    uses.reserve(triangles.size() * 3);
    for (const auto& t : triangles) {
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = t[k], b = t[(k + 1) % 3];
            uses.push_back({std::min(a, b), std::max(a, b), a > b});
        }
    }
    std::sort(uses.begin(), uses.end());
    EdgeCensus census;
    for (size_t i = 0; i < uses.size();) {
        const uint32_t low = uses[i].low, high = uses[i].high;
        uint32_t forward = 0, backward = 0;
        for (; i < uses.size() && uses[i].low == low && uses[i].high == high; ++i) {
            ++(uses[i].backward ? backward : forward);
        }
        census.add_edge(forward, backward, low == high);
    }
    return census;
}

}  // namespace nq::npr::adjacency

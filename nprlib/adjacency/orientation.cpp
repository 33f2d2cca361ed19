#include "adjacency/orientation.h"

#include <algorithm>
#include <compare>

namespace nq::npr::adjacency {

namespace {

// Two triangles sharing an edge that no other triangle uses.
struct Link {
    uint32_t a, b;
    bool same_direction;  // both traverse the edge the same way: one of them must flip
};

struct EdgeUse {
    uint32_t low, high, triangle;
    bool backward;
    auto operator<=>(const EdgeUse&) const = default;
};

std::vector<Link> two_triangle_links(std::span<const SoupTriangle> triangles) {
    std::vector<EdgeUse> uses;
    uses.reserve(triangles.size() * 3);
    for (uint32_t t = 0; t < triangles.size(); ++t) {
        const auto& w = triangles[t].welded;
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = w[k], b = w[(k + 1) % 3];
            uses.push_back({std::min(a, b), std::max(a, b), t, a > b});
        }
    }
    std::sort(uses.begin(), uses.end());
    std::vector<Link> links;
    for (size_t i = 0; i < uses.size();) {
        size_t j = i;
        while (j < uses.size() && uses[j].low == uses[i].low && uses[j].high == uses[i].high) ++j;
        if (j - i == 2) {
            links.push_back(
                {uses[i].triangle, uses[i + 1].triangle, uses[i].backward == uses[i + 1].backward});
        }
        i = j;
    }
    return links;
}

// Compressed adjacency: neighbours of triangle t are entries [start[t], start[t + 1]).
struct LinkGraph {
    std::vector<uint32_t> start;
    std::vector<uint32_t> link;  // index into links
};

LinkGraph link_graph(size_t num_triangles, const std::vector<Link>& links) {
    LinkGraph g;
    g.start.assign(num_triangles + 1, 0);
    for (const Link& l : links) {
        ++g.start[l.a + 1];
        ++g.start[l.b + 1];
    }
    for (size_t t = 0; t < num_triangles; ++t) g.start[t + 1] += g.start[t];
    g.link.resize(g.start.back());
    std::vector<uint32_t> fill(g.start.begin(), g.start.end() - 1);
    for (uint32_t i = 0; i < links.size(); ++i) {
        g.link[fill[links[i].a]++] = i;
        g.link[fill[links[i].b]++] = i;
    }
    return g;
}

// Breadth-first from `seed`, appending to plan.order; returns how many triangles it reached.
size_t orient_piece(uint32_t seed, const std::vector<Link>& links, const LinkGraph& graph,
                    std::vector<uint8_t>& visited, OrientationPlan& plan) {
    const size_t first = plan.order.size();
    visited[seed] = 1;
    plan.order.push_back(seed);
    for (size_t head = first; head < plan.order.size(); ++head) {
        const uint32_t t = plan.order[head];
        for (uint32_t i = graph.start[t]; i < graph.start[t + 1]; ++i) {
            const Link& l = links[graph.link[i]];
            const uint32_t other = l.a == t ? l.b : l.a;
            if (visited[other]) continue;
            visited[other] = 1;
            plan.flipped[other] = plan.flipped[t] ^ uint8_t(l.same_direction);
            plan.order.push_back(other);
        }
    }
    return plan.order.size() - first;
}

// Keep the file's majority orientation in the piece at order[first, end).
void keep_majority(OrientationPlan& plan, size_t first) {
    size_t flipped = 0;
    for (size_t i = first; i < plan.order.size(); ++i) flipped += plan.flipped[plan.order[i]];
    if (2 * flipped <= plan.order.size() - first) return;
    for (size_t i = first; i < plan.order.size(); ++i) plan.flipped[plan.order[i]] ^= 1;
}

}  // namespace

OrientationPlan plan_orientation(std::span<const SoupTriangle> triangles) {
    const std::vector<Link> links = two_triangle_links(triangles);
    const LinkGraph graph = link_graph(triangles.size(), links);
    OrientationPlan plan;
    plan.flipped.assign(triangles.size(), 0);
    plan.order.reserve(triangles.size());
    std::vector<uint8_t> visited(triangles.size(), 0);
    for (uint32_t seed = 0; seed < triangles.size(); ++seed) {
        if (visited[seed]) continue;
        const size_t first = plan.order.size();
        orient_piece(seed, links, graph, visited, plan);
        keep_majority(plan, first);
        ++plan.components;
    }
    for (uint8_t f : plan.flipped) plan.flipped_count += f;
    for (const Link& l : links) {
        if ((plan.flipped[l.a] ^ plan.flipped[l.b]) != uint8_t(l.same_direction)) ++plan.conflicts;
    }
    return plan;
}

}  // namespace nq::npr::adjacency

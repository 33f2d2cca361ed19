#include "adjacency/verdict.h"

#include <cstdio>

namespace nq::npr::adjacency {

namespace {

std::string percent(double share) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f%%", share * 100.0);
    return text;
}

}  // namespace

const char* edge_style_name(EdgeStyle style) {
    return style == EdgeStyle::true_edges ? "true silhouettes and creases" : "back-face lines";
}

Verdict judge_adjacency(const RecoveryStats& stats, const std::vector<std::string>& problems,
                        double min_manifold_share) {
    Verdict v;
    const double share = stats.mesh.consistent_share();
    const std::string figures = percent(share) + " of " + std::to_string(stats.mesh.edges) +
                                " edges manifold and consistently oriented, " +
                                std::to_string(stats.mesh.boundary) + " boundary";
    if (!problems.empty()) {
        v.reason = "mesh check failed: " + problems.front();
    } else if (stats.mesh.non_manifold > 0) {
        v.reason = std::to_string(stats.mesh.non_manifold) + " non-manifold edges remain";
    } else if (stats.mesh.edges == 0) {
        v.reason = "no usable triangles";
    } else if (share < min_manifold_share) {
        v.reason = figures + " (below " + percent(min_manifold_share) + ")";
    } else {
        v.style = EdgeStyle::true_edges;
        v.reason = figures;
    }
    return v;
}

}  // namespace nq::npr::adjacency

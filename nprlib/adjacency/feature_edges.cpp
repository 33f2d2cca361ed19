#include "adjacency/feature_edges.h"

#include <algorithm>
#include <cmath>

#include <glm/trigonometric.hpp>

namespace nq::npr::adjacency {

const char* feature_edge_name(FeatureEdge kind) {
    switch (kind) {
        case FeatureEdge::none:
            return "none";
        case FeatureEdge::border:
            return "border";
        case FeatureEdge::silhouette:
            return "silhouette";
        case FeatureEdge::ridge:
            return "ridge";
        case FeatureEdge::valley:
            return "valley";
    }
    return "?";
}

float crease_cosine(float degrees) {
    return std::cos(glm::radians(std::clamp(degrees, 0.0f, 180.0f)));
}

void find_feature_edges(std::span<const EdgeRecord> records, const glm::vec3* positions,
                        const glm::vec3& eye, const FeatureTest& test,
                        std::vector<ClassifiedEdge>& out) {
    out.clear();
    for_each_feature_edge(records, positions, eye, test,
                          [&](uint32_t e, const EdgeRecord&, FeatureEdge kind) {
                              out.push_back({e, kind});
                          });
}

}  // namespace nq::npr::adjacency

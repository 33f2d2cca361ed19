#include "adjacency/edge_queries.h"

namespace nq::npr::adjacency {

namespace {

bool opposite_facing(float height0, float height1) {
    return height0 * height1 <= 0.0f;
}

}  // namespace

bool is_silhouette(const MeshEdge& edge, const PoseGeometry& geometry, uint32_t pose,
                   const glm::vec3& eye) {
    if (edge.boundary()) return true;
    return opposite_facing(eye_height(geometry.plane(pose, edge.face0), eye),
                           eye_height(geometry.plane(pose, edge.face1), eye));
}

void find_silhouette_edges(const EdgeTable& table, const PoseGeometry& geometry, uint32_t pose,
                           const glm::vec3& eye, std::vector<uint32_t>& out) {
    out.clear();
    for (uint32_t e = 0; e < table.edges.size(); ++e) {
        if (is_silhouette(table.edges[e], geometry, pose, eye)) out.push_back(e);
    }
}

void find_silhouette_edges_blended(const EdgeTable& table, const PoseGeometry& geometry,
                                   uint32_t pose0, uint32_t pose1, float lerp, const glm::vec3& eye,
                                   std::vector<uint32_t>& out) {
    out.clear();
    auto height = [&](uint32_t face) {
        return eye_height(geometry.plane(pose0, face), eye) * (1.0f - lerp) +
               eye_height(geometry.plane(pose1, face), eye) * lerp;
    };
    for (uint32_t e = 0; e < table.edges.size(); ++e) {
        const MeshEdge& edge = table.edges[e];
        if (edge.boundary() || opposite_facing(height(edge.face0), height(edge.face1))) {
            out.push_back(e);
        }
    }
}

const char* crease_name(Crease crease) {
    switch (crease) {
        case Crease::none:
            return "none";
        case Crease::ridge:
            return "ridge";
        case Crease::valley:
            return "valley";
    }
    return "?";
}

void find_creases(const PoseGeometry& geometry, uint32_t pose, float threshold_radians,
                  std::vector<uint32_t>& ridges, std::vector<uint32_t>& valleys) {
    ridges.clear();
    valleys.clear();
    for (uint32_t e = 0; e < geometry.num_edges; ++e) {
        switch (classify_crease(geometry.signed_dihedral(pose, e), threshold_radians)) {
            case Crease::ridge:
                ridges.push_back(e);
                break;
            case Crease::valley:
                valleys.push_back(e);
                break;
            case Crease::none:
                break;
        }
    }
}

}  // namespace nq::npr::adjacency

#include "technical/alias_edge_mesh.h"

#include <glm/geometric.hpp>

#include "adjacency/model_adjacency.h"
#include "classic/alias_mesh.h"
#include "technical/shadow_mesh.h"

namespace nq::npr::technical {
namespace {

EdgeKind drawn_kind(adjacency::FeatureEdge kind) {
    switch (kind) {
        case adjacency::FeatureEdge::ridge:
            return EdgeKind::ridge;
        case adjacency::FeatureEdge::valley:
            return EdgeKind::valley;
        default:
            return EdgeKind::silhouette;  // silhouettes and open borders
    }
}

}  // namespace

adjacency::FeatureTest EdgeQuery::feature_test() const {
    adjacency::FeatureTest test;
    test.outline = silhouettes      ? adjacency::Outline::silhouettes
                   : backface_lines ? adjacency::Outline::elsewhere
                                    : adjacency::Outline::ignored;
    test.creases = creases;
    test.cos_crease = cos_crease;
    return test;
}

std::unique_ptr<AliasEdgeMesh> AliasEdgeMesh::create(const nqr_alias_model& model,
                                                     std::string& error) {
    if (!classic::validate_alias_model(model, error)) return nullptr;
    adjacency::ModelAdjacency recovered = adjacency::recover_adjacency(model);
    std::unique_ptr<AliasEdgeMesh> mesh(new AliasEdgeMesh());
    mesh->stats_ = recovered.stats;
    mesh->verdict_ = std::move(recovered.verdict);
    mesh->vertex_count_ = model.num_vertices;
    mesh->edges_ = std::move(recovered.edges.records);
    mesh->file_ = std::move(recovered.file);
    mesh->shadow_triangles_ = technical::shadow_triangles(recovered.mesh);
    if (mesh->shadow_triangles_.empty()) mesh->shadow_triangles_ = mesh->file_.triangles;
    mesh->facing_away_.reserve(mesh->file_.triangles.size());
    return mesh;
}

void AliasEdgeMesh::find_edges(const glm::vec3* pose, const glm::vec3& eye, const EdgeQuery& query,
                               std::vector<FoundEdge>& out) const {
    if (!pose) return;
    if (query.backface_lines) find_backface_lines(pose, eye, out);
    if (query.silhouettes || query.creases) find_true_edges(pose, eye, query, out);
}

void AliasEdgeMesh::find_true_edges(const glm::vec3* pose, const glm::vec3& eye,
                                    const EdgeQuery& query, std::vector<FoundEdge>& out) const {
    adjacency::for_each_feature_edge(
        edges_, pose, eye, query.feature_test(),
        [&](uint32_t, const adjacency::EdgeRecord& edge, adjacency::FeatureEdge kind) {
            out.push_back({edge.v0, edge.v1, drawn_kind(kind)});
        });
}

void AliasEdgeMesh::find_backface_lines(const glm::vec3* pose, const glm::vec3& eye,
                                        std::vector<FoundEdge>& out) const {
    const std::vector<Triangle>& triangles = file_.triangles;
    facing_away_.resize(triangles.size());
    for (size_t t = 0; t < triangles.size(); ++t) {
        const Triangle& tri = triangles[t];
        const glm::vec3& p0 = pose[tri[0]];
        const glm::vec3 normal = glm::cross(pose[tri[1]] - p0, pose[tri[2]] - p0);
        facing_away_[t] = adjacency::has_area(normal) && !adjacency::faces_eye(normal, p0, eye);
    }
    for (size_t t = 0; t < triangles.size(); ++t) {
        if (!facing_away_[t]) continue;
        for (uint32_t k = 0; k < 3; ++k) {
            const int32_t twin = file_.twins[t][k];
            if (twin >= 0 && facing_away_[static_cast<size_t>(twin)]) continue;  // hidden
            out.push_back({triangles[t][k], triangles[t][(k + 1) % 3], EdgeKind::backface});
        }
    }
}

EdgeQuery plan_edge_query(const AliasEdgeMesh& mesh, const EdgeSettings& s) {
    const bool fallback = s.backface_lines == BackfaceLines::always ||
                          (s.backface_lines == BackfaceLines::unclean_models && !mesh.clean());
    const bool has_adjacency = mesh.edge_count() > 0;
    EdgeQuery query;
    query.backface_lines = s.silhouettes && fallback && !mesh.triangles().empty();
    query.silhouettes = s.silhouettes && !fallback && has_adjacency;
    query.creases =
        s.creases && has_adjacency && (mesh.clean() || s.backface_lines == BackfaceLines::never);
    query.cos_crease = adjacency::crease_cosine(s.crease_angle_degrees);
    return query;
}

std::string AliasEdgeMesh::verdict_line(const std::string& model_name) const {
    return adjacency::verdict_log_line(model_name, verdict_);
}

}  // namespace nq::npr::technical

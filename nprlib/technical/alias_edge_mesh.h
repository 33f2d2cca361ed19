// An alias model's edges for the technical style, built once at registration from the recovered
// adjacency (adjacency::recover_adjacency), and searched on the CPU every frame for the entity's
// blended pose and the true eye (Gooch et al. 1999, Raskar 2001):
//   - true edges: the adjacency's edge records, classified by adjacency::classify_edge
//     (feature_edges.h: silhouettes, open borders, ridges and valleys);
//   - the paper's thick back-face lines, for models whose adjacency is not trustworthy: the
//     edges of every back-facing triangle of the file (no adjacency needed), less the sides it
//     shares with a twin (adjacency::FileTriangles) that faces away too: such a side lies on
//     the far side of the model, where front faces hide it.
// The adjacency verdict says whether true edges can be trusted. This class keeps what drawing
// needs and does the shading-independent part of the search; no GL here: AliasEdgeDrawer
// turns what find_edges returns into quads.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "adjacency/edge_table.h"
#include "adjacency/feature_edges.h"
#include "adjacency/file_triangles.h"
#include "adjacency/recovery_stats.h"
#include "adjacency/verdict.h"
#include "nqr_renderer.h"
#include "technical/edge_glsl.h"
#include "technical/technical_settings.h"

namespace nq::npr::technical {

// What to look for on one model (plan_edge_query turns the settings into it).
struct EdgeQuery {
    bool silhouettes = false;     // true silhouettes from adjacency
    bool creases = false;         // ridges and valleys (an edge that is a silhouette is none)
    bool backface_lines = false;  // back-facing triangles' edges, in place of true silhouettes
    float cos_crease = 0.5f;      // an edge is a crease when its normals' cosine is below this
    bool any() const { return silhouettes || creases || backface_lines; }
    // The adjacency's test for the true edges this query asks for.
    adjacency::FeatureTest feature_test() const;
};

struct FoundEdge {
    uint32_t v0, v1;  // MDL vertex indices
    EdgeKind kind;
};

class AliasEdgeMesh {
  public:
    using Triangle = adjacency::FileTriangle;

    // Null with `error` set when the model cannot be read (see classic::validate_alias_model).
    static std::unique_ptr<AliasEdgeMesh> create(const nqr_alias_model& model, std::string& error);

    // The verdict: true silhouettes and creases are trustworthy for this model.
    bool clean() const { return verdict_.style == adjacency::EdgeStyle::true_edges; }
    const adjacency::RecoveryStats& stats() const { return stats_; }
    const adjacency::Verdict& verdict() const { return verdict_; }
    // The line adjacency::verdict_log_line gives: "adjacency: NAME: <style> (<figures>)".
    std::string verdict_line(const std::string& model_name) const;

    uint32_t vertex_count() const { return vertex_count_; }
    size_t edge_count() const { return edges_.size(); }
    // The file's usable triangles, counter-clockwise seen from outside.
    std::span<const Triangle> triangles() const { return file_.triangles; }
    // The triangles its shadow is cast with (shadow_mesh.h), likewise.
    std::span<const Triangle> shadow_triangles() const { return shadow_triangles_; }
    // Per MDL vertex: the lowest-numbered MDL vertex at its welded position (skin seams
    // duplicate vertices in the file), itself where there is no other.
    std::span<const uint32_t> seam_representatives() const { return file_.seam_representatives; }

    // Appends to `out` the edges `query` asks for on `pose` (vertex_count() model-space
    // positions) seen from `eye` (model space). Each edge at most once.
    void find_edges(const glm::vec3* pose, const glm::vec3& eye, const EdgeQuery& query,
                    std::vector<FoundEdge>& out) const;

  private:
    AliasEdgeMesh() = default;
    void find_true_edges(const glm::vec3* pose, const glm::vec3& eye, const EdgeQuery& query,
                         std::vector<FoundEdge>& out) const;
    void find_backface_lines(const glm::vec3* pose, const glm::vec3& eye,
                             std::vector<FoundEdge>& out) const;

    uint32_t vertex_count_ = 0;
    std::vector<adjacency::EdgeRecord> edges_;
    adjacency::FileTriangles file_;  // back-face lines and seams
    std::vector<Triangle> shadow_triangles_;
    mutable std::vector<uint8_t> facing_away_;  // scratch of find_backface_lines
    adjacency::RecoveryStats stats_;
    adjacency::Verdict verdict_;
};

// The settings' plan for one model: true silhouettes for clean models, back-face lines in their
// place for unclean ones (or always / never, by setting); creases where the adjacency is trusted
// (or wherever there is adjacency when back-face lines are refused altogether).
EdgeQuery plan_edge_query(const AliasEdgeMesh& mesh, const EdgeSettings& settings);

}  // namespace nq::npr::technical

// GPU side of an alias model's edges, built once at registration from the recovered adjacency
// (adjacency::recover_adjacency): one vertex per MDL vertex carrying its skin coordinate
// ((s + 0.5) / w, (t + 0.5) / h, front side of the seam), so a vertex shader finds k_d there
// and the MDL vertex index is gl_VertexID (what pose_position()/pose_normal() take), and one
// element buffer holding two index ranges:
//   - the adjacency range: EdgeTable::triangles_adjacency, 6 MDL indices per mesh face, for
//     GL_TRIANGLES_ADJACENCY (true silhouettes and creases);
//   - the triangle range: the file's triangles, 3 MDL indices each, reversed to wind
//     counter-clockwise seen from outside, for the back-face-line fallback (needs no adjacency);
//   - the edge range: one GL_LINES_ADJACENCY primitive per mesh edge (face0's third corner,
//     the edge's two ends, the neighbour's far corner), what the edge drawer draws: one
//     geometry-shader invocation per edge, emitting at most one quad.
// The adjacency verdict says whether the first range can be trusted.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "adjacency/recovery_stats.h"
#include "adjacency/verdict.h"
#include "gl/handles.h"
#include "nqr_renderer.h"

namespace nq::npr::technical {

class AliasEdgeMesh {
  public:
    // Null with `error` set when the model cannot be read (see classic::validate_alias_model).
    static std::unique_ptr<AliasEdgeMesh> create(gl::ObjectTracker* tracker,
                                                 const nqr_alias_model& model, std::string& error);

    // The verdict: true silhouettes and creases are trustworthy for this model.
    bool clean() const { return verdict_.style == adjacency::EdgeStyle::true_edges; }
    const adjacency::RecoveryStats& stats() const { return stats_; }
    const adjacency::Verdict& verdict() const { return verdict_; }
    // The line adjacency::verdict_log_line gives: "adjacency: NAME: <style> (<figures>)".
    std::string verdict_line(const std::string& model_name) const;

    GLuint vertex_array() const { return vertex_array_.id(); }
    GLsizei adjacency_index_count() const { return adjacency_count_; }  // 6 per face
    GLsizei triangle_index_count() const { return triangle_count_; }    // 3 per triangle
    GLsizei edge_index_count() const { return edge_count_; }            // 4 per edge
    const void* edge_indices_offset() const;
    // Byte offset of the triangle range in the element buffer (for glDrawElements).
    const void* triangle_indices_offset() const;
    GLuint index_buffer() const { return indices_.id(); }

    // The edge range's primitives (4 MDL indices each) that can be a silhouette or a crease of
    // `entity`'s blended pose seen from entity.eye_model: the geometry shader, which decides,
    // then runs over tens of edges instead of every edge (llvmpipe runs geometry and vertex
    // shading on one thread). Conservative: facing tests within a small tolerance of zero and
    // creases within one degree of the threshold are kept. Writes into storage owned by the
    // mesh (no allocation); valid until the next call.
    std::span<const uint32_t> candidate_edges(const nqr_entity& entity, float cos_crease,
                                              bool creases) const;

  private:
    AliasEdgeMesh() = default;

    gl::VertexArray vertex_array_;
    gl::Buffer skin_coords_, indices_;
    GLsizei adjacency_count_ = 0, triangle_count_ = 0, edge_count_ = 0;
    const nqr_alias_model* model_ = nullptr;    // valid until the model is released
    std::vector<uint32_t> edge_prims_;          // the edge range, kept on the CPU
    mutable std::vector<glm::vec3> positions_;  // scratch: the blended pose
    mutable std::vector<uint32_t> candidates_;  // scratch: what candidate_edges returns
    adjacency::RecoveryStats stats_;
    adjacency::Verdict verdict_;
};

}  // namespace nq::npr::technical

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
#include <string>

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

  private:
    AliasEdgeMesh() = default;

    gl::VertexArray vertex_array_;
    gl::Buffer skin_coords_, indices_;
    GLsizei adjacency_count_ = 0, triangle_count_ = 0, edge_count_ = 0;
    adjacency::RecoveryStats stats_;
    adjacency::Verdict verdict_;
};

}  // namespace nq::npr::technical

// GPU side of a brush model's edges (brush_edge_table.h), one per nqr_brush_model (the world and
// its "*N" submodels share one): a static vertex buffer with two vertices per edge for GL_LINES,
// each carrying what the geometry shader needs to classify the edge every frame — both faces'
// planes, the signed dihedral angle, whether it is a boundary edge — and the edge's surface
// colour (the average colour of its faces' textures, for white addition and distance fade; the
// world keeps classic lighting, so the texture average stands in for the lit colour).
// Also the per-frame scratch for listing the edges of the visible surfaces, sized here once so
// that frames never allocate.
#pragma once

#include <epoxy/gl.h>

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "gl/handles.h"
#include "nqr_renderer.h"
#include "technical/brush_edge_table.h"

namespace nq::npr::technical {

// One vertex of the edge buffer (both vertices of an edge carry the same edge data).
struct BrushEdgeVertex {
    float position[3];  // model space
    float plane0[4];    // face0: normal, dist (front side: dot(normal, p) > dist)
    float plane1[4];    // face1; face0's again for boundary edges
    float dihedral_degrees;
    float boundary;    // 1: one face only
    uint8_t color[4];  // surface colour, RGB (+ unused alpha)
};

class BrushEdgeMesh {
  public:
    // nullptr with `error` set when the model's arrays cannot be used. Without a palette the
    // surface colour is mid-grey.
    static std::unique_ptr<BrushEdgeMesh> create(gl::ObjectTracker* tracker,
                                                 const nqr_brush_model& brush, std::string& error,
                                                 const uint8_t* palette_rgb = nullptr);

    const BrushEdgeStats& stats() const { return table_.stats(); }
    const BrushEdgeTable& table() const { return table_; }
    uint32_t num_edges() const { return static_cast<uint32_t>(table_.edges().size()); }
    GLuint vertex_array() const { return vertex_array_.id(); }

    // GL_LINES indices (2e, 2e + 1 for edge e) of the shared edges of `surfaces`, each edge
    // once, less the flat ones (faces in one plane: never a silhouette, never a crease; BSP
    // splits leave many); surface indices out of range are skipped. The span points into this
    // mesh's scratch and stays valid until the next call (one thread, the GL thread, calls it).
    std::span<const uint32_t> line_indices_of(std::span<const uint32_t> surfaces) const;

  private:
    BrushEdgeMesh() = default;
    void upload(gl::ObjectTracker* tracker, const std::vector<BrushEdgeVertex>& vertices);
    void index_drawable_edges();

    BrushEdgeTable table_;
    gl::VertexArray vertex_array_;
    gl::Buffer vertices_;
    // Per surface (first_drawable_[s] to first_drawable_[s + 1] in drawable_edges_), its shared
    // edges that are not flat, made once at create.
    std::vector<uint32_t> first_drawable_, drawable_edges_;
    // Per-frame scratch: an edge is listed when its stamp differs from the call's stamp.
    mutable std::vector<uint32_t> line_indices_;  // capacity 2 per edge, reserved at create
    mutable std::vector<uint32_t> edge_stamps_;
    mutable uint32_t stamp_ = 0;
};

}  // namespace nq::npr::technical

// Silhouette and crease edges of alias models (MDL) in the technical style. The edges are found
// on the CPU (AliasEdgeMesh::find_edges, on the pose blended once per frame) and each becomes a
// quad of constant pixel width (edge_glsl.h) drawn by a vertex shader alone: four vertices per
// edge, two at each end, coloured from the surface shaded under that end (technical_shade on
// the pose normal, for white addition and distance fade). No geometry shader: on llvmpipe one
// costs more than the whole CPU search, and a GPU draws the quads just as well.
//
// A frame's edges are gathered first (begin_frame, add_entity per entity, upload: one stream
// upload for every entity) and then drawn pass by pass (begin, draw_entity per entity, end),
// so the program and the per-frame uniforms are set once per pass, not per entity.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "classic/alias_model_gpu.h"
#include "classic/frame_view.h"
#include "gl/handles.h"
#include "gl/program.h"
#include "gl/stream_buffer.h"
#include "nqr_renderer.h"
#include "technical/alias_edge_mesh.h"
#include "technical/edge_glsl.h"
#include "technical/technical_settings.h"

namespace nq::npr::technical {

// One entity's quads in the frame's batch.
struct EdgeSpan {
    size_t first_edge = 0;
    size_t edge_count = 0;
};

class AliasEdgeDrawer {
  public:
    bool init(gl::ObjectTracker* tracker, std::string& error);
    void reset();

    // Gathering. begin_frame empties the batch; add_entity finds the entity's edges on `pose`
    // (mesh.vertex_count() model-space positions) seen from entity.eye_model and appends their
    // quads; upload sends the batch to the GPU (after the last add_entity, before drawing).
    void begin_frame();
    EdgeSpan add_entity(const nqr_entity& entity, const AliasEdgeMesh& mesh,
                        const glm::vec3* pose, const EdgeSettings& settings);
    void upload();

    // Drawing, after the entities' faces (the depth buffer holds them). begin starts from
    // frame_view.h's state, end restores it; the depth range is the caller's (the view model's
    // squeeze). skin_texture: mipmapped, k_d is read from it; the pose normals come from `faces`.
    void begin(const classic::FrameView& view, const EdgeFrameUniforms& frame_uniforms,
               const TechnicalSettings& settings);
    void draw_entity(const classic::FrameView& view, const nqr_entity& entity,
                     const classic::AliasModelGpu& faces, GLuint skin_texture, EdgeSpan span);
    void end();

    // All of the above for one entity (its pose blended here).
    void draw_entity(const classic::FrameView& view, const EdgeFrameUniforms& frame_uniforms,
                     const nqr_entity& entity, const classic::AliasModelGpu& faces,
                     const AliasEdgeMesh& edges, GLuint skin_texture,
                     const TechnicalSettings& settings);

    size_t edges_in_batch() const { return corners_.size() / 4; }

  private:
    // One vertex of an edge's quad (model space), 32 bytes.
    struct Corner {
        glm::vec3 own, other;
        uint16_t uv[2];   // own end's skin coordinate, normalised
        uint32_t packed;  // side (bit 0) | EdgeKind (bits 1-2) | own end's MDL vertex << 3
    };

    gl::Program program_;
    gl::StreamBuffer stream_;
    gl::Buffer quad_indices_;  // 0 1 2 0 2 3 per quad, for every quad a push can hold
    gl::VertexArray vertex_array_;
    size_t max_edges_ = 0;
    std::vector<Corner> corners_;
    std::vector<FoundEdge> found_;       // scratch: one entity's edges
    std::vector<glm::vec3> pose_;        // scratch: the convenience draw_entity's pose
    size_t base_vertex_ = 0;             // where upload put corners_[0], in corners
    bool uploaded_ = false;
};

}  // namespace nq::npr::technical

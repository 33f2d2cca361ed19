// Silhouette and crease edges of alias models (MDL) in the technical style. The edges are found
// on the CPU (AliasEdgeMesh::find_edges, on the pose blended once per frame) and drawn without a
// geometry shader, in two GPU steps:
//   - shading: one transform-feedback pass over every MDL vertex of every entity with edges
//     (points, rasteriser off) writes its view-space position, distance from the eye and the
//     surface colour shaded there (technical_shade on the pose normal) into a buffer: each
//     vertex is shaded once, however many edges meet at it;
//   - quads: each edge becomes a quad of constant pixel width (edge_glsl.h), four vertices that
//     only know the indices of the edge's two ends in that buffer; the vertex shader reads the
//     ends, colours the edge (white addition, distance fade) and offsets the corner on screen.
// A frame's edges are gathered first (begin_frame, add_entity per entity, upload: the corners
// in one stream upload, then the shading pass) and drawn pass by pass (begin, draw per span of
// edges, end): no per-entity state, so the spans of neighbouring entities go in one draw.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
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
    // Vertices the shading pass can hold in one frame (all entities with edges together).
    static constexpr uint32_t kMaxShadedVertices = 1u << 17;

    bool init(gl::ObjectTracker* tracker, std::string& error);
    void reset();

    // Gathering. begin_frame empties the batch; add_entity finds the entity's edges on `pose`
    // (mesh.vertex_count() model-space positions) seen from entity.eye_model, appends their
    // quads and schedules its vertices for shading (skin_texture: mipmapped, k_d is read from
    // it; the pose normals come from `faces`); upload sends the quads and runs the shading
    // pass (after the last add_entity, before drawing).
    void begin_frame();
    EdgeSpan add_entity(const nqr_entity& entity, const classic::AliasModelGpu& faces,
                        GLuint skin_texture, const AliasEdgeMesh& mesh, const glm::vec3* pose,
                        const EdgeSettings& settings);
    void upload(const classic::FrameView& view, const ShadingSettings& shading);

    // Drawing, after the entities' faces (the depth buffer holds them). begin starts from
    // frame_view.h's state, end restores it; the depth range is the caller's (the view model's
    // squeeze).
    void begin(const EdgeFrameUniforms& frame_uniforms, const EdgeSettings& settings);
    void draw(EdgeSpan span);
    void end();

    // All of the above for one entity (its pose blended here).
    void draw_entity(const classic::FrameView& view, const EdgeFrameUniforms& frame_uniforms,
                     const nqr_entity& entity, const classic::AliasModelGpu& faces,
                     const AliasEdgeMesh& edges, GLuint skin_texture,
                     const TechnicalSettings& settings);

    size_t edges_in_batch() const { return corners_.size() / 4; }

  private:
    // One vertex of an edge's quad: the ends' rows in the shaded-vertex buffer. 12 bytes.
    struct Corner {
        uint32_t own, other;
        uint32_t side_and_kind;  // side (bit 0) | EdgeKind << 1
    };
    // An entity whose vertices the shading pass shades, from row `first_row` on.
    struct ShadedEntity {
        const nqr_entity* entity;
        const classic::AliasModelGpu* faces;
        GLuint skin;
        uint32_t first_row;
    };
    void shade_vertices(const classic::FrameView& view, const ShadingSettings& shading);

    gl::Program quads_, shading_;
    gl::StreamBuffer corner_stream_;
    gl::Buffer quad_indices_;     // 0 1 2 0 2 3 per quad, for every quad a push can hold
    gl::Buffer shaded_;           // transform feedback output, 2 RGBA32F texels per vertex
    gl::Texture shaded_texture_;  // the same buffer, as a buffer texture for the quads
    gl::VertexArray quads_array_, points_array_;
    size_t max_edges_ = 0;
    std::vector<Corner> corners_;
    std::vector<ShadedEntity> shaded_entities_;
    std::vector<glm::vec2> skin_coords_;  // per shaded row: its MDL vertex's skin coordinate
    uint32_t shaded_rows_ = 0;
    std::vector<FoundEdge> found_;  // scratch: one entity's edges
    std::vector<glm::vec3> pose_;   // scratch: the convenience draw_entity's pose
    bool uploaded_ = false;
};

}  // namespace nq::npr::technical

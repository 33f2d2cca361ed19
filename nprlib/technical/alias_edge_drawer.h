// Silhouette and crease edges of alias models (MDL) in the technical style. The edges are found
// on the CPU (AliasEdgeMesh::find_edges, on the pose blended once per frame), joined where a
// chain of them runs straight on screen (edge_chains.h), their ends shaded
// there too (shading_model.h: each end's view-space position, distance from the eye and the
// surface colour under it, once per vertex however many edges meet at it), and each edge becomes
// a quad of constant pixel width (edge_glsl.h): four vertices carrying both ends, whose vertex
// shader colours the edge (white addition, distance fade) and offsets the corner on screen. No
// geometry shader and no GPU pass before the quads.
// A frame's edges are gathered first (begin_frame, add_entity per entity, upload: the corners
// in one stream upload) and drawn pass by pass (begin, draw per span of edges, end): no
// per-entity state, so the spans of neighbouring entities go in one draw.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "abi/frame_view.h"
#include "classic/alias_model_gpu.h"
#include "gl/handles.h"
#include "gl/program.h"
#include "gl/stream_buffer.h"
#include "nqr_renderer.h"
#include "technical/alias_edge_mesh.h"
#include "technical/edge_chains.h"
#include "technical/edge_glsl.h"
#include "technical/skin_tones.h"
#include "technical/technical_settings.h"

namespace nq::npr::technical {

// One entity's quads in the frame's batch.
struct EdgeSpan {
    size_t first_edge = 0;
    size_t edge_count = 0;
};

// The chain tolerance for a frame: settings.merge_pixels at the frame's pixel size.
ChainTolerance chain_tolerance(const EdgeFrameUniforms& frame, const EdgeSettings& settings);

class AliasEdgeDrawer {
  public:
    bool init(gl::ObjectTracker* tracker, std::string& error);
    void reset();

    // Gathering. begin_frame empties the batch and takes the frame's camera, tones and the
    // chain tolerance (EdgeSettings::merge_pixels);
    // add_entity finds the entity's edges on `pose` (mesh.vertex_count() model-space positions)
    // seen from entity.eye_model, shades their ends (normals from `faces`' pose texels, k_d from
    // `skin`) and appends their quads; upload sends the quads (after the last add_entity,
    // before drawing).
    void begin_frame(const npr::FrameView& view, const ShadingSettings& shading,
                     const ChainTolerance& chains);
    EdgeSpan add_entity(const nqr_entity& entity, const classic::AliasModelGpu& faces,
                        const AliasEdgeMesh& mesh, const glm::vec3* pose, const SkinSample& skin,
                        const EdgeSettings& settings);
    void upload();

    // Drawing, after the entities' faces (the depth buffer holds them). begin starts from
    // frame_view.h's state, end restores it; the depth range is the caller's (the view model's
    // squeeze).
    void begin(const EdgeFrameUniforms& frame_uniforms, const EdgeSettings& settings);
    void draw(EdgeSpan span);
    void end();

    // All of the above for one entity (its pose blended here).
    void draw_entity(const npr::FrameView& view, const EdgeFrameUniforms& frame_uniforms,
                     const nqr_entity& entity, const classic::AliasModelGpu& faces,
                     const AliasEdgeMesh& edges, const SkinSample& skin,
                     const TechnicalSettings& settings);

    size_t edges_in_batch() const { return corners_.size() / 4; }

  private:
    // One vertex of an edge's quad: both ends (view space), this end's distance from the eye
    // and shaded colour. 32 bytes.
    struct Corner {
        glm::vec3 own;
        float distance;
        glm::vec3 other;
        uint8_t shaded[3];
        uint8_t side_and_kind;  // side (bit 0) | EdgeKind << 1
    };
    class EndShader;
    void clear();
    void new_entity_stamp(uint32_t vertex_count);
    void place_ends(const EndShader& shader);
    void append_quads(const EndShader& shader, size_t count);

    gl::Program quads_;
    gl::StreamBuffer corner_stream_;
    gl::Buffer quad_indices_;  // 0 1 2 0 2 3 per quad, for every quad a push can hold
    gl::VertexArray quads_array_;
    size_t max_edges_ = 0;
    npr::FrameView view_;
    ShadingSettings shading_;
    ChainTolerance chain_tolerance_;
    EdgeChains chains_;
    std::vector<Corner> corners_;
    // Scratch for one entity: its edges; by MDL vertex, the view-space positions, and the
    // shaded colours and distances, of edge ends, valid where the stamps equal stamp_ (a new
    // stamp per entity).
    struct ShadedEnd {
        uint8_t rgb[3];
        float distance;  // from the eye
    };
    std::vector<FoundEdge> found_;
    std::vector<glm::vec3> end_views_;
    std::vector<ShadedEnd> shaded_ends_;
    std::vector<uint32_t> view_stamps_, colour_stamps_;
    uint32_t stamp_ = 0;
    std::vector<glm::vec3> pose_;  // scratch: the convenience draw_entity's pose
    bool uploaded_ = false;
};

}  // namespace nq::npr::technical

// Draws planar shadows of alias models: each caster's pose (blended once per frame on the CPU)
// flattened onto its floor by each ShadowPass's matrix, in the shadow colour, blended over the
// world already drawn.
//   - A frame's shadows are gathered first (begin_frame, add_entity per caster: the light-facing
//     triangles, projected on the CPU straight to clip space) and drawn together (draw): one
//     draw per pass kind (the umbra or hard shadow, and each penumbra), whatever the number of
//     casters, so the state is set once.
//   - Depth-tested against the world without writing depth, pulled toward the eye by a polygon
//     offset so the shadow neither z-fights its floor nor visibly floats above it.
//   - A flattened model overlaps itself (front and back faces, folded limbs): the stencil keeps
//     each pass kind from darkening a pixel twice. Shadows of different casters merge the same
//     way, as two shadows of one light do; the umbra and penumbra kinds still stack. Each
//     frame marks the stencil with reference values of its own, so it is cleared only every
//     85 frames (or when the framebuffer changes); nothing else may write the stencil.
//   - Only colour attachment 0 is written (normals in a G-buffer stay the floor's).
// The framebuffer needs a stencil buffer; without one overlapping triangles darken twice.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "abi/frame_view.h"
#include "gl/handles.h"
#include "gl/program.h"
#include "gl/stream_buffer.h"
#include "nqr_renderer.h"
#include "technical/alias_edge_mesh.h"
#include "technical/planar_shadow.h"
#include "technical/technical_settings.h"

namespace nq::npr::technical {

class ShadowDrawer {
  public:
    bool init(gl::ObjectTracker* tracker, std::string& error);
    void reset();

    // Empties the frame's batch.
    void begin_frame();

    // Adds one caster: `pose` (mesh.vertex_count() model-space positions) through
    // entity.model_matrix, each pass's world_to_plane and view.view_projection, at each pass's
    // alpha. Only triangles facing passes.light are kept: on a closed model the others project
    // inside them.
    void add_entity(const npr::FrameView& view, const nqr_entity& entity, const AliasEdgeMesh& mesh,
                    const glm::vec3* pose, const ShadowPasses& passes);

    // Draws what was added, in settings.color. Starts from and restores the classic drawers'
    // state, stencil test off.
    void draw(const ShadowSettings& settings);

    size_t triangles_in_batch() const;

  private:
    struct Vertex {
        glm::vec4 clip;
        float alpha;
    };
    static constexpr int kKinds = 3;  // the umbra (or hard shadow) and two penumbrae
    bool next_stencil_values();

    gl::Program program_;
    gl::StreamBuffer vertex_stream_, index_stream_;
    gl::VertexArray vertex_array_;
    // Each caster's vertices once per pass (projected), and per pass kind the light-facing
    // triangles as indices into them: a vertex is shaded once, not once per triangle.
    std::vector<Vertex> vertices_;
    std::array<std::vector<uint32_t>, kKinds> indices_;
    std::vector<uint32_t> lit_;  // scratch: one caster's light-facing triangles
    // This frame's stencil values are stencil_base_ + 1 ... + kKinds, in stencil_framebuffer_.
    int stencil_base_ = 0;
    GLint stencil_framebuffer_ = -1;
};

}  // namespace nq::npr::technical

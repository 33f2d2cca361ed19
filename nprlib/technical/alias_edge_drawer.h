// Silhouette and crease edges of alias models (MDL) in the technical style, found on the GPU
// every frame for the entity's blended pose and the true eye (Gooch et al. 1999, Raskar 2001):
//   - true edges: GL_TRIANGLES_ADJACENCY hands a geometry shader each face with its three
//     neighbours. An edge is a silhouette where the face looks at the eye and the neighbour
//     does not (emitted by the front face only, so once); a crease where the normals turn by
//     more than the crease angle (a ridge when convex, a valley when concave), emitted once, by
//     a front face. Open borders (the neighbour is the face itself reversed) are outlines seen
//     from either side;
//   - the paper's thick back-face lines, for models whose adjacency is not trustworthy (or
//     always, by setting): every back-facing triangle's edges as wide quads at their own depth,
//     so the front faces hide them except beyond the outline. Creases stay for clean models.
// Each edge becomes a quad of constant pixel width (edge_glsl.h) coloured from the shaded
// surface under it (technical_shade per vertex), for white addition and distance fade.
#pragma once

#include <string>

#include "classic/alias_model_gpu.h"
#include "classic/frame_view.h"
#include "gl/program.h"
#include "gl/stream_buffer.h"
#include "nqr_renderer.h"
#include "technical/alias_edge_mesh.h"
#include "technical/edge_glsl.h"
#include "technical/technical_settings.h"

namespace nq::npr::technical {

class AliasEdgeDrawer {
  public:
    bool init(gl::ObjectTracker* tracker, std::string& error);
    void reset();

    // One entity's edges, after its faces (the depth buffer holds them). Starts from and
    // restores frame_view.h's state; the depth range is the caller's (the view model's squeeze).
    // skin_texture: mipmapped, k_d is read from it. Light: entity.light.direction (world space).
    void draw_entity(const classic::FrameView& view, const EdgeFrameUniforms& frame_uniforms,
                     const nqr_entity& entity, const classic::AliasModelGpu& faces,
                     const AliasEdgeMesh& edges, GLuint skin_texture,
                     const TechnicalSettings& settings);

  private:
    void set_entity_uniforms(gl::Program& program, const classic::FrameView& view,
                             const EdgeFrameUniforms& frame_uniforms, const nqr_entity& entity,
                             const classic::AliasModelGpu& faces,
                             const TechnicalSettings& settings);
    // silhouettes: 0 off, 1 drawn here, 2 drawn by the back-face lines (so no creases there).
    void draw_true_edges(const nqr_entity& entity, const AliasEdgeMesh& edges, int silhouettes,
                         bool creases, const EdgeSettings& settings);
    void draw_backface_lines(const AliasEdgeMesh& edges);

    gl::Program true_edges_;
    gl::Program backface_lines_;
    gl::StreamBuffer candidates_;  // each entity's candidate edges, as element indices
};

}  // namespace nq::npr::technical

// Draws the silhouettes and creases of brush geometry (BrushEdgeMesh) for the technical style.
// Each edge goes to a geometry shader as a line; per frame and per view it decides:
//   silhouette — one face toward the eye, the other away;
//   ridge / valley — both faces toward the eye and the faces bending by more than
//                    settings.crease_angle_degrees (convex: ridge, concave: valley);
//   nothing otherwise (both faces away, or a flat joint).
// Boundary edges (one face only: the edge of a hole, a face beside sky) are not drawn for the
// world, whose holes are where sky or other models are; for brush entities they are drawn as
// silhouettes while their face is toward the eye, which outlines open shapes such as a lone
// panel. Edges then become quads through edge_glsl's emit_edge(), coloured by edge_color() from
// each edge's surface colour.
// Draw after the faces: edges are pulled toward the eye by settings.depth_offset and depth-tested
// against them. GL state: starts from and restores frame_view.h's state (stencil untouched).
#pragma once

#include <span>
#include <string>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "abi/frame_view.h"
#include "gl/program.h"
#include "gl/stream_buffer.h"
#include "nqr_renderer.h"
#include "technical/brush_edge_mesh.h"
#include "technical/edge_glsl.h"
#include "technical/technical_settings.h"

namespace nq::npr::technical {

class BrushEdgeDrawer {
  public:
    bool init(gl::ObjectTracker* tracker, std::string& error);
    void reset();

    // Edges of the world's visible surfaces (frame.visible_surfaces, indices into the brush's
    // surfaces; when the list is NULL, every shared edge of the mesh).
    void draw_world(const npr::FrameView& view, const EdgeFrameUniforms& frame_uniforms,
                    const nqr_frame& frame, const BrushEdgeMesh& mesh,
                    const EdgeSettings& settings);

    // All edges of surfaces [first_surface, first_surface + num_surfaces) of one brush entity
    // (placed by entity.model_matrix; facing tested from entity.eye_model, in model space).
    void draw_entity(const npr::FrameView& view, const EdgeFrameUniforms& frame_uniforms,
                     const nqr_entity& entity, const BrushEdgeMesh& mesh, uint32_t first_surface,
                     uint32_t num_surfaces, const EdgeSettings& settings);

  private:
    struct Placement {
        glm::mat4 model{1.0f};
        glm::vec3 eye_model{0.0f};
        bool boundaries = false;
    };

    void begin(const npr::FrameView& view, const EdgeFrameUniforms& frame_uniforms,
               const Placement& placement, const BrushEdgeMesh& mesh, const EdgeSettings& settings);
    void draw_indexed(std::span<const uint32_t> line_indices);
    void end();

    gl::Program program_;
    gl::StreamBuffer indices_;  // per-frame index lists of the world's visible edges
};

}  // namespace nq::npr::technical

// Draws planar shadows of alias models: the posed model flattened onto the floor by each
// ShadowPass's matrix, in the shadow colour, blended over the world already drawn.
//   - Depth-tested against the world without writing depth, pulled toward the eye by a polygon
//     offset so the shadow neither z-fights its floor nor visibly floats above it.
//   - A flattened model overlaps itself (front and back faces, folded limbs); the stencil keeps
//     each pass from darkening a pixel twice: every pass draws where the stencil is not its own
//     reference and writes that reference. References increase per pass through the frame; the
//     stencil is cleared only before the first pass of a frame and when the 8-bit range wraps.
//   - Only colour attachment 0 is written (normals in a G-buffer stay the floor's).
// The framebuffer needs a stencil buffer; without one overlapping triangles darken twice.
#pragma once

#include <string>

#include "classic/alias_model_gpu.h"
#include "classic/frame_view.h"
#include "gl/program.h"
#include "nqr_renderer.h"
#include "technical/planar_shadow.h"
#include "technical/technical_settings.h"

namespace nq::npr::technical {

class ShadowDrawer {
  public:
    bool init(gl::ObjectTracker* tracker, std::string& error);
    void reset();

    // Call once at the start of a frame's shadow drawing (resets the stencil reference scheme;
    // the stencil is cleared before the frame's first pass).
    void begin_frame();

    // The model (blended pose, model_matrix, then each pass's world_to_plane, then
    // view_projection) in settings.color at each pass's alpha. Starts from and restores the
    // classic drawers' state, stencil test off.
    void draw_entity(const classic::FrameView& view, const nqr_entity& entity,
                     const classic::AliasModelGpu& model, const ShadowPasses& passes,
                     const ShadowSettings& settings);

  private:
    // The stencil reference for the next pass, clearing the stencil when none is left unused.
    GLint next_stencil_reference();

    gl::Program program_;
    GLint next_reference_ = 0;  // 0: the stencil holds values from before; clear it first
};

}  // namespace nq::npr::technical

// Scoped GL state for drawing a 2D overlay on top of a rendered frame: alpha blending on;
// depth test, stencil test, face culling and scissor off; filled polygons, every colour channel
// written, the viewport over the whole screen. Whatever these were before comes back when the
// scope ends, so a renderer plugin's state (wireframe outlines, masks) survives, and what it
// left set cannot hide the console.
#pragma once

#include <epoxy/gl.h>

#include <array>

namespace nq {

class OverlayGlState {
  public:
    OverlayGlState(int width, int height);
    ~OverlayGlState();
    OverlayGlState(const OverlayGlState&) = delete;
    OverlayGlState& operator=(const OverlayGlState&) = delete;

  private:
    GLboolean blend_, depth_test_, stencil_test_, cull_face_, scissor_test_;
    std::array<GLboolean, 4> colour_mask_{};
    std::array<GLint, 2> polygon_mode_{};
    GLint blend_src_rgb_, blend_dst_rgb_, blend_src_alpha_, blend_dst_alpha_;
    GLint blend_equation_rgb_, blend_equation_alpha_;
    std::array<GLint, 4> viewport_{};
};

}  // namespace nq

#include "draw2d/overlay_gl_state.h"

namespace nq {
namespace {

void set_enabled(GLenum capability, GLboolean on) {
    if (on) {
        glEnable(capability);
    } else {
        glDisable(capability);
    }
}

}  // namespace

OverlayGlState::OverlayGlState(int width, int height)
    : blend_(glIsEnabled(GL_BLEND)),
      depth_test_(glIsEnabled(GL_DEPTH_TEST)),
      stencil_test_(glIsEnabled(GL_STENCIL_TEST)),
      cull_face_(glIsEnabled(GL_CULL_FACE)),
      scissor_test_(glIsEnabled(GL_SCISSOR_TEST)) {
    glGetIntegerv(GL_BLEND_SRC_RGB, &blend_src_rgb_);
    glGetIntegerv(GL_BLEND_DST_RGB, &blend_dst_rgb_);
    glGetIntegerv(GL_BLEND_SRC_ALPHA, &blend_src_alpha_);
    glGetIntegerv(GL_BLEND_DST_ALPHA, &blend_dst_alpha_);
    glGetIntegerv(GL_BLEND_EQUATION_RGB, &blend_equation_rgb_);
    glGetIntegerv(GL_BLEND_EQUATION_ALPHA, &blend_equation_alpha_);
    glGetIntegerv(GL_VIEWPORT, viewport_.data());
    glGetBooleanv(GL_COLOR_WRITEMASK, colour_mask_.data());
    glGetIntegerv(GL_POLYGON_MODE, polygon_mode_.data());  // core: front and back are one

    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_SCISSOR_TEST);
    glViewport(0, 0, width, height);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
}

OverlayGlState::~OverlayGlState() {
    set_enabled(GL_BLEND, blend_);
    set_enabled(GL_DEPTH_TEST, depth_test_);
    set_enabled(GL_STENCIL_TEST, stencil_test_);
    set_enabled(GL_CULL_FACE, cull_face_);
    set_enabled(GL_SCISSOR_TEST, scissor_test_);
    glBlendEquationSeparate(static_cast<GLenum>(blend_equation_rgb_),
                            static_cast<GLenum>(blend_equation_alpha_));
    glBlendFuncSeparate(static_cast<GLenum>(blend_src_rgb_), static_cast<GLenum>(blend_dst_rgb_),
                        static_cast<GLenum>(blend_src_alpha_),
                        static_cast<GLenum>(blend_dst_alpha_));
    glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
    glColorMask(colour_mask_[0], colour_mask_[1], colour_mask_[2], colour_mask_[3]);
    glPolygonMode(GL_FRONT_AND_BACK, static_cast<GLenum>(polygon_mode_[0]));
}

}  // namespace nq

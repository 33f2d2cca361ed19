// The `gamma` and `contrast` cvars, as QuakeSpasm applies them: every colour channel of the
// finished frame becomes min(channel * contrast, 1)^gamma (gamma below 1 brighter, above 1
// darker; contrast above 1 brighter, saturating). The frame is copied into a texture and drawn
// back through a small shader -- a full-screen pass, so it runs only when either is not 1; at
// gamma 1 and contrast 1 apply() returns at once and costs nothing.
//
//   auto pass = GammaPass::create();                 // a GL context must be current
//   after the last thing drawn, before the swap: pass->apply({gamma, contrast}, width, height);
//
// apply() works on (0, 0, width, height) of the bound framebuffer and puts back the GL state
// it changes (program, vertex array, texture binding, blending, depth, cull, scissor,
// stencil, viewport, colour mask, polygon mode).
#pragma once

#include "common/result.h"
#include "gl/program.h"

namespace nq {

struct ScreenLevels {
    float gamma = 1.0f;
    float contrast = 1.0f;
    bool identity() const { return gamma == 1.0f && contrast == 1.0f; }
};

class GammaPass {
  public:
    static Result<GammaPass> create();

    void apply(const ScreenLevels& levels, int width, int height);

  private:
    explicit GammaPass(npr::gl::Program program);

    npr::gl::Program program_;
    npr::gl::VertexArray empty_vertex_array_;  // the triangle comes from gl_VertexID
    npr::gl::Texture frame_copy_;
    int copy_width_ = 0, copy_height_ = 0;
    GLint gamma_location_ = -1;
    GLint contrast_location_ = -1;
};

}  // namespace nq

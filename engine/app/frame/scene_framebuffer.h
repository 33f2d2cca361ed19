// The offscreen framebuffer a post-processing plugin reads: colour (RGBA8), view-space normals
// (RGBA8, n * 0.5 + 0.5, written by every scene shader to output 1) and depth (24-bit texture).
// Created on first use, resized with the viewport, released with the dispatcher.
#pragma once

#include <cstdint>

#include "nqr_renderer.h"

namespace nq {

class SceneFramebuffer {
  public:
    SceneFramebuffer() = default;
    ~SceneFramebuffer();
    SceneFramebuffer(const SceneFramebuffer&) = delete;
    SceneFramebuffer& operator=(const SceneFramebuffer&) = delete;

    // Makes sure the textures match width x height; false when the driver refuses them.
    bool prepare(int width, int height);
    // Binds it for drawing both colour outputs and clears colour, normals and depth.
    void bind_and_clear();
    const nqr_gbuffer& gbuffer() const { return gbuffer_; }
    void release();

  private:
    nqr_gbuffer gbuffer_{sizeof(nqr_gbuffer), 0, 0, 0, 0, 0, 0};
};

}  // namespace nq

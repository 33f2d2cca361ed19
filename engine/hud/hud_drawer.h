// Draws the engine's overlays on the game screen through a QuadRenderer
// (draw2d/quad_renderer.h), between the renderer plugin's 3D view and the console, in one pass
// and one draw call:
//   first  one full-screen blended quad of the frame's colour shifts (client/view_blend.h;
//          GLQuake's polyblend), when there is a tint;
//   then   the status bar, inventory, scoreboards, intermission and crosshair (hud_scene.h),
//          from one atlas texture of HudPictures.
// It leaves the GL state as it found it and makes no GL calls when there is nothing to draw.
#pragma once

#include <cstddef>

#include "client/client_state.h"
#include "client/view_blend.h"
#include "common/result.h"
#include "draw2d/quad_renderer.h"
#include "gl/handles.h"
#include "hud/hud_pictures.h"
#include "hud/hud_scene.h"

namespace nq {

inline constexpr size_t kHudQuadCapacity = 1024;  // more than a full deathmatch ranking

class HudDrawer {
  public:
    static Result<HudDrawer> create();

    HudDrawer(HudDrawer&&) noexcept = default;
    HudDrawer& operator=(HudDrawer&&) = delete;

    // Takes the pictures and uploads their atlas (a GL context must be current).
    void set_pictures(HudPictures pictures);
    const HudPictures& pictures() const { return pictures_; }

    // `with_hud` false: the tint alone.
    void draw(const ClientState& client, const ScreenBlend& blend, const HudFrame& frame,
              bool with_hud = true);

    // Another overlay's quads (the menu's), built by build(QuadBatch&, const HudPictures&)
    // with this drawer's pictures, over what the screen shows.
    template <typename Build>
    void draw_overlay(int width, int height, Build&& build) {
        if (width <= 0 || height <= 0) return;
        QuadRenderer::Pass pass(renderer_, width, height);
        if (atlas_) pass.use_texture(atlas_.id());
        build(pass.batch(), pictures_);
    }

    // Statistics of the latest draw(), for tests.
    size_t draw_calls() const { return drawn_ ? renderer_.draw_calls() : 0; }
    size_t quads_drawn() const { return drawn_ ? renderer_.quads_drawn() : 0; }

  private:
    explicit HudDrawer(QuadRenderer renderer) : renderer_(std::move(renderer)) {}

    QuadRenderer renderer_;
    HudPictures pictures_;
    npr::gl::Texture atlas_;
    bool drawn_ = false;
};

}  // namespace nq

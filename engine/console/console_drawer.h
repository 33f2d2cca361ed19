// Draws the console through a QuadRenderer (draw2d/quad_renderer.h): the font atlas as a
// texture (conchars or the built-in font) and an optional background picture
// (gfx/conback.lmp when the game has one).
//
//   auto drawer = ConsoleDrawer::create();              // a GL context must be current
//   drawer->set_font(*load_conchars_font(wad, palette)); // optional: else the built-in font
//   every frame, after the 3D view: drawer->draw(console);
//
// draw() covers the viewport (0, 0, screen size of console.layout()) of the bound framebuffer,
// blending over what is there, and leaves the GL state as it found it (QuadRenderer::Pass).
// With nothing to show it makes no GL calls at all.
#pragma once

#include <cstddef>

#include "common/result.h"
#include "console/console.h"
#include "console/console_font.h"
#include "console/console_scene.h"
#include "draw2d/quad_renderer.h"
#include "gl/handles.h"

namespace nq {

class ConsoleDrawer {
  public:
    static Result<ConsoleDrawer> create(ConsoleStyle style = {});

    ConsoleDrawer(ConsoleDrawer&& other) noexcept = default;
    ConsoleDrawer& operator=(ConsoleDrawer&&) = delete;

    // A 128x128 font atlas (conchars_to_rgba / load_conchars_font). Other sizes are ignored.
    void set_font(const RgbaImage& font);
    void use_fallback_font() { set_font(fallback_font()); }
    // A picture behind the console instead of the dark translucent fill; empty: back to fill.
    void set_background(const RgbaImage& image);
    bool has_background() const { return static_cast<bool>(background_); }

    void draw(const Console& console);

    // Statistics of the latest draw(), for tests and the frame overlay.
    size_t draw_calls() const { return drawn_ ? renderer_.draw_calls() : 0; }
    size_t quads_drawn() const { return drawn_ ? renderer_.quads_drawn() : 0; }

  private:
    ConsoleDrawer(QuadRenderer renderer, ConsoleStyle style);

    QuadRenderer renderer_;
    npr::gl::Texture font_;
    npr::gl::Texture background_;
    ConsoleScene scene_;
    bool drawn_ = false;  // whether the latest draw() drew anything
};

}  // namespace nq

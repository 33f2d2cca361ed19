// Draws the console with OpenGL 3.3 core: one shader, one streaming vertex buffer fed from a
// fixed QuadBatch, the font atlas as a texture (conchars or the built-in font) and an optional
// background picture (gfx/conback.lmp when the game has one).
//
//   auto drawer = ConsoleDrawer::create();              // a GL context must be current
//   drawer->set_font(*load_conchars_font(wad, palette)); // optional: else the built-in font
//   every frame, after the 3D view: drawer->draw(console);
//
// draw() covers the viewport (0, 0, screen size of console.layout()) of the bound framebuffer,
// blending over what is there. It sets what it needs (blend on; depth, cull, scissor off; its
// program, vertex array, buffer and texture unit 0) and puts all of that back afterwards, so
// the renderer's state survives. With nothing to show it makes no GL calls at all.
#pragma once

#include <cstddef>
#include <span>

#include "common/result.h"
#include "console/console.h"
#include "console/console_font.h"
#include "console/console_scene.h"
#include "console/quad_batch.h"
#include "video/gl_objects.h"

namespace nq {

class ConsoleDrawer {
  public:
    static Result<ConsoleDrawer> create(ConsoleStyle style = {});

    ConsoleDrawer(ConsoleDrawer&& other) noexcept;
    ConsoleDrawer& operator=(ConsoleDrawer&&) = delete;

    // A 128x128 font atlas (conchars_to_rgba / load_conchars_font). Other sizes are ignored.
    void set_font(const RgbaImage& font);
    void use_fallback_font() { set_font(fallback_font()); }
    // A picture behind the console instead of the dark translucent fill; empty: back to fill.
    void set_background(const RgbaImage& image);
    bool has_background() const { return static_cast<bool>(background_); }

    void draw(const Console& console);

    // Statistics of the latest draw(), for tests and the frame overlay.
    size_t draw_calls() const { return draw_calls_; }
    size_t quads_drawn() const { return quads_drawn_; }

  private:
    ConsoleDrawer(GlProgram program, ConsoleStyle style);
    void create_buffers();
    void upload_indices();
    void flush(std::span<const QuadVertex> vertices);
    void draw_background_image(const Console& console);

    GlProgram program_;
    GlVertexArray vertex_array_;
    GlBuffer vertex_buffer_;
    GlBuffer index_buffer_;
    GlTexture font_;
    GlTexture background_;
    GLint screen_size_location_ = -1;
    ConsoleScene scene_;
    QuadBatch batch_;
    size_t draw_calls_ = 0;
    size_t quads_drawn_ = 0;
};

}  // namespace nq

// Draws QuadBatch quads with OpenGL 3.3 core: the quad shader, one streaming vertex buffer the
// size of the batch, a fixed index buffer. Every 2D overlay (screen blends, status bar,
// console) draws through one of these.
//
//   auto renderer = QuadRenderer::create();   // a GL context must be current
//   {
//       QuadRenderer::Pass pass(*renderer, screen_width, screen_height);
//       pass.use_texture(atlas);               // flushes what was queued for the previous one
//       pass.batch().image(...);               // pixels, y down
//   }                                          // flushes, puts the GL state back
//
// A pass covers the viewport (0, 0, width, height) of the bound framebuffer and blends over
// what is there. It sets what it needs (OverlayGlState; its program, vertex array, buffer,
// texture unit 0) and restores all of it when it ends, so the renderer's state survives.
#pragma once

#include <cstddef>
#include <span>

#include "common/result.h"
#include "draw2d/overlay_gl_state.h"
#include "draw2d/quad_batch.h"
#include "gl/program.h"

namespace nq {

class QuadRenderer {
  public:
    static Result<QuadRenderer> create(size_t capacity_quads = kQuadBatchCapacity);

    QuadRenderer(QuadRenderer&& other) noexcept;
    QuadRenderer& operator=(QuadRenderer&&) = delete;

    class Pass {
      public:
        Pass(QuadRenderer& renderer, int width, int height);
        ~Pass();
        Pass(const Pass&) = delete;
        Pass& operator=(const Pass&) = delete;

        QuadBatch& batch() { return renderer_.batch_; }
        // Textured quads queued from now on sample `texture` (quads queued before still
        // sample the previous one: they are drawn first).
        void use_texture(GLuint texture);

      private:
        // Keeps the caller's program, vertex array, buffer and texture bindings.
        class BindingRestore {
          public:
            BindingRestore();
            ~BindingRestore();
            BindingRestore(const BindingRestore&) = delete;
            BindingRestore& operator=(const BindingRestore&) = delete;

          private:
            GLint vertex_array_ = 0, program_ = 0, active_texture_ = 0, texture_ = 0,
                  array_buffer_ = 0;
        };

        QuadRenderer& renderer_;
        OverlayGlState state_;
        BindingRestore bindings_;
    };

    // Statistics of the latest pass, for tests and the frame overlay.
    size_t draw_calls() const { return draw_calls_; }
    size_t quads_drawn() const { return quads_drawn_; }

  private:
    QuadRenderer(npr::gl::Program program, size_t capacity_quads);
    void create_buffers();
    void upload_indices();
    void flush(std::span<const QuadVertex> vertices);

    npr::gl::Program program_;
    npr::gl::VertexArray vertex_array_;
    npr::gl::Buffer vertex_buffer_;
    npr::gl::Buffer index_buffer_;
    GLint screen_size_location_ = -1;
    QuadBatch batch_;
    size_t draw_calls_ = 0;
    size_t quads_drawn_ = 0;
};

}  // namespace nq

// The lightmap atlas on the GPU: one RGBA8 2D array texture (a layer per packer page) and its CPU
// copy. Surfaces are rebuilt into the CPU copy; each layer remembers the rectangle that changed,
// and upload_dirty() sends only those rectangles (GLQuake likewise re-uploaded only the changed
// rows of modified lightmap blocks).
#pragma once

#include <cstdint>
#include <vector>

#include "gl/handles.h"

namespace nq::npr::classic {

class LightmapAtlas {
  public:
    // Allocates `pages` layers of page_size^2 texels, black.
    void create(gl::ObjectTracker* tracker, int page_size, int pages);
    void reset();

    // Start of texel (x, y) of a page in the CPU copy; rows are row_bytes() apart.
    uint8_t* texel(int page, int x, int y);
    size_t row_bytes() const { return static_cast<size_t>(page_size_) * 4; }

    void mark_dirty(int page, int x, int y, int width, int height);
    void upload_dirty();  // binds the texture to GL_TEXTURE_2D_ARRAY on the active unit

    GLuint texture() const { return texture_.id(); }
    int page_size() const { return page_size_; }
    int pages() const { return pages_; }
    int uploads() const { return uploads_; }  // rectangles uploaded so far (for tests)

  private:
    struct DirtyRect {
        int x0, y0, x1, y1;  // x1 <= x0: clean
    };

    gl::Texture texture_;
    std::vector<uint8_t> pixels_;
    std::vector<DirtyRect> dirty_;
    int page_size_ = 0;
    int pages_ = 0;
    int uploads_ = 0;
};

}  // namespace nq::npr::classic

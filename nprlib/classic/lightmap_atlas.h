// The lightmap atlas on the GPU: RGBA8 2D array textures (a layer per packer page) and their CPU
// copy. Surfaces are rebuilt into the CPU copy; upload_dirty() sends only the rectangles that
// changed (GLQuake likewise re-uploaded only the changed rows of modified lightmap blocks).
//
// The atlas is a ring of kLightmapRing textures, and a frame that changes a lightmap writes the
// next one in the ring instead of the one the last frames drew with. Writing a texture the GPU
// may still be reading makes the driver wait for those frames to finish (on Mesa llvmpipe every
// animated light style or dynamic light cost 6-15 ms that way, 10 times a second). Each ring
// texture keeps its own changed rectangle per page, so it catches up on everything that
// changed since it was last current.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "gl/handles.h"

namespace nq::npr::classic {

// Four: the frame being drawn plus the three a driver may still be working on with a
// triple-buffered swap chain (with three, frames lit by a dynamic light, which changes every
// frame, still waited). This engine swaps a frame only once the one before it is finished, so
// two would do for it; the ABI does not promise that of every engine.
inline constexpr int kLightmapRing = 4;

class LightmapAtlas {
  public:
    // Allocates `pages` layers of page_size^2 texels, black, in every ring texture.
    void create(gl::ObjectTracker* tracker, int page_size, int pages);
    void reset();

    // Start of texel (x, y) of a page in the CPU copy; rows are row_bytes() apart.
    uint8_t* texel(int page, int x, int y);
    size_t row_bytes() const { return static_cast<size_t>(page_size_) * 4; }

    void mark_dirty(int page, int x, int y, int width, int height);
    // After a frame's mark_dirty calls: when anything changed, moves to the next ring texture
    // and brings it up to date (binding it to GL_TEXTURE_2D_ARRAY on the active unit).
    void upload_dirty();

    GLuint texture() const { return ring_[static_cast<size_t>(current_)].id(); }  // to draw with
    int page_size() const { return page_size_; }
    int pages() const { return pages_; }
    int uploads() const { return uploads_; }  // rectangles uploaded so far (for tests)

  private:
    struct DirtyRect {
        int x0, y0, x1, y1;  // x1 <= x0: clean
        void add(int ax0, int ay0, int ax1, int ay1);
    };

    std::array<gl::Texture, kLightmapRing> ring_;
    std::array<std::vector<DirtyRect>, kLightmapRing> dirty_;  // per ring texture, per page
    std::vector<uint8_t> pixels_;
    int current_ = 0;
    bool changed_ = false;  // mark_dirty since the last upload_dirty
    int page_size_ = 0;
    int pages_ = 0;
    int uploads_ = 0;
};

}  // namespace nq::npr::classic

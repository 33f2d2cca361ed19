#include "classic/lightmap_atlas.h"

#include <epoxy/gl.h>

#include <algorithm>

namespace nq::npr::classic {

void LightmapAtlas::create(gl::ObjectTracker* tracker, int page_size, int pages) {
    reset();
    page_size_ = page_size;
    pages_ = std::max(pages, 1);  // a layer even with no lightmaps, so the sampler is complete
    pixels_.assign(static_cast<size_t>(page_size_) * page_size_ * 4 * pages_, 0);
    dirty_.assign(static_cast<size_t>(pages_), DirtyRect{0, 0, 0, 0});
    texture_ = gl::Texture::create(tracker);
    glBindTexture(GL_TEXTURE_2D_ARRAY, texture_.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_RGBA8, page_size_, page_size_, pages_, 0, GL_RGBA,
                 GL_UNSIGNED_BYTE, pixels_.data());
    // Lightmaps are smooth gradients: bilinear, no mipmaps (as GLQuake).
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
}

void LightmapAtlas::reset() {
    texture_.reset();
    pixels_.clear();
    pixels_.shrink_to_fit();
    dirty_.clear();
    page_size_ = pages_ = 0;
}

uint8_t* LightmapAtlas::texel(int page, int x, int y) {
    const size_t page_bytes = static_cast<size_t>(page_size_) * page_size_ * 4;
    return pixels_.data() + page_bytes * page + static_cast<size_t>(y) * row_bytes() +
           static_cast<size_t>(x) * 4;
}

void LightmapAtlas::mark_dirty(int page, int x, int y, int width, int height) {
    DirtyRect& rect = dirty_[static_cast<size_t>(page)];
    if (rect.x1 <= rect.x0) {
        rect = {x, y, x + width, y + height};
        return;
    }
    rect.x0 = std::min(rect.x0, x);
    rect.y0 = std::min(rect.y0, y);
    rect.x1 = std::max(rect.x1, x + width);
    rect.y1 = std::max(rect.y1, y + height);
}

void LightmapAtlas::upload_dirty() {
    bool bound = false;
    for (int page = 0; page < pages_; ++page) {
        DirtyRect& rect = dirty_[static_cast<size_t>(page)];
        if (rect.x1 <= rect.x0) continue;
        if (!bound) {
            glBindTexture(GL_TEXTURE_2D_ARRAY, texture_.id());
            glPixelStorei(GL_UNPACK_ROW_LENGTH, page_size_);
            glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
            bound = true;
        }
        glTexSubImage3D(GL_TEXTURE_2D_ARRAY, 0, rect.x0, rect.y0, page, rect.x1 - rect.x0,
                        rect.y1 - rect.y0, 1, GL_RGBA, GL_UNSIGNED_BYTE,
                        texel(page, rect.x0, rect.y0));
        rect = {0, 0, 0, 0};
        ++uploads_;
    }
    if (bound) glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
}

}  // namespace nq::npr::classic

#include "classic/lightmap_atlas.h"

#include <epoxy/gl.h>

#include <algorithm>

namespace nq::npr::classic {

void LightmapAtlas::create(gl::ObjectTracker* tracker, int page_size, int pages) {
    reset();
    page_size_ = page_size;
    pages_ = std::max(pages, 1);  // a layer even with no lightmaps, so the sampler is complete
    pixels_.assign(static_cast<size_t>(page_size_) * page_size_ * 4 * pages_, 0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    for (int k = 0; k < kLightmapRing; ++k) {
        dirty_[k].assign(static_cast<size_t>(pages_), DirtyRect{0, 0, 0, 0});
        ring_[k] = gl::Texture::create(tracker);
        glBindTexture(GL_TEXTURE_2D_ARRAY, ring_[k].id());
        glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_RGBA8, page_size_, page_size_, pages_, 0, GL_RGBA,
                     GL_UNSIGNED_BYTE, pixels_.data());
        // Lightmaps are smooth gradients: bilinear, no mipmaps (as GLQuake).
        glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    }
    glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
}

void LightmapAtlas::reset() {
    for (int k = 0; k < kLightmapRing; ++k) {
        ring_[k].reset();
        dirty_[k].clear();
    }
    pixels_.clear();
    pixels_.shrink_to_fit();
    current_ = 0;
    changed_ = false;
    page_size_ = pages_ = 0;
}

uint8_t* LightmapAtlas::texel(int page, int x, int y) {
    const size_t page_bytes = static_cast<size_t>(page_size_) * page_size_ * 4;
    return pixels_.data() + page_bytes * page + static_cast<size_t>(y) * row_bytes() +
           static_cast<size_t>(x) * 4;
}

void LightmapAtlas::DirtyRect::add(int ax0, int ay0, int ax1, int ay1) {
    if (x1 <= x0) {
        *this = {ax0, ay0, ax1, ay1};
        return;
    }
    x0 = std::min(x0, ax0);
    y0 = std::min(y0, ay0);
    x1 = std::max(x1, ax1);
    y1 = std::max(y1, ay1);
}

void LightmapAtlas::mark_dirty(int page, int x, int y, int width, int height) {
    for (auto& rects : dirty_) rects[static_cast<size_t>(page)].add(x, y, x + width, y + height);
    changed_ = true;
}

void LightmapAtlas::upload_dirty() {
    if (!changed_) return;
    changed_ = false;
    current_ = (current_ + 1) % kLightmapRing;
    glBindTexture(GL_TEXTURE_2D_ARRAY, texture());
    glPixelStorei(GL_UNPACK_ROW_LENGTH, page_size_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    for (int page = 0; page < pages_; ++page) {
        DirtyRect& rect = dirty_[static_cast<size_t>(current_)][static_cast<size_t>(page)];
        if (rect.x1 <= rect.x0) continue;
        glTexSubImage3D(GL_TEXTURE_2D_ARRAY, 0, rect.x0, rect.y0, page, rect.x1 - rect.x0,
                        rect.y1 - rect.y0, 1, GL_RGBA, GL_UNSIGNED_BYTE,
                        texel(page, rect.x0, rect.y0));
        rect = {0, 0, 0, 0};
        ++uploads_;
    }
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
}

}  // namespace nq::npr::classic

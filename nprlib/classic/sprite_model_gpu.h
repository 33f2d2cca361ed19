// GPU side of a sprite model: one mipmapped RGBA texture per image, palette index 255 transparent
// (alpha-tested when drawn), plus each image's size and offset from the entity origin.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "gl/handles.h"
#include "nqr_renderer.h"

namespace nq::npr::classic {

struct SpriteImageGpu {
    gl::Texture texture;
    float width = 0, height = 0;
    float origin_x = 0, origin_y = 0;  // offset of the top-left corner from the entity origin
};

class SpriteModelGpu {
  public:
    static std::unique_ptr<SpriteModelGpu> create(gl::ObjectTracker* tracker,
                                                  const nqr_sprite_model& model,
                                                  const uint8_t* palette_rgb, std::string& error);

    uint32_t type() const { return type_; }
    // nullptr when out of range or the image had no pixels.
    const SpriteImageGpu* image(uint32_t index) const;
    uint32_t image_count() const { return static_cast<uint32_t>(images_.size()); }

  private:
    uint32_t type_ = 0;
    std::vector<SpriteImageGpu> images_;
};

}  // namespace nq::npr::classic

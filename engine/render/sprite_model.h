// A sprite (SPR) as the renderer ABI's nqr_sprite_model: every picture in one array in frame
// order, frames as ranges of it with their intervals. Owns the Spr and the arrays.
#pragma once

#include <memory>
#include <vector>

#include "formats/spr.h"
#include "nqr_renderer.h"

namespace nq {

class SpriteModelData {
  public:
    static std::shared_ptr<const SpriteModelData> build(Spr spr);

    SpriteModelData(const SpriteModelData&) = delete;
    SpriteModelData& operator=(const SpriteModelData&) = delete;

    const nqr_sprite_model& abi() const { return sprite_; }
    const Spr& spr() const { return spr_; }
    // The farthest picture corner from the sprite origin: sprites turn to face the viewer, so
    // their bounds are the cube of this radius.
    float radius() const { return radius_; }

  private:
    SpriteModelData() = default;
    void convert();
    void link_abi();

    Spr spr_;
    std::vector<nqr_sprite_image> images_;
    std::vector<std::vector<float>> intervals_;
    std::vector<nqr_sprite_frame> frames_;
    float radius_ = 0.0f;
    nqr_sprite_model sprite_{};
};

}  // namespace nq

#include "render/sprite_model.h"

#include <algorithm>
#include <cmath>

#include "render/alias_model.h"  // kDefaultAnimationInterval

namespace nq {

namespace {

nqr_sprite_image image_record(const SprPicture& picture) {
    nqr_sprite_image image{};
    image.size = sizeof(nqr_sprite_image);
    image.width = picture.width;
    image.height = picture.height;
    image.origin_x = picture.origin_x;
    image.origin_y = picture.origin_y;
    image.pixels = picture.pixels.empty() ? nullptr : picture.pixels.data();
    return image;
}

// Quake places a picture from origin_x (left) to origin_x + width (right) and from origin_y
// (top) down to origin_y - height (bottom), in the sprite's plane.
float corner_radius(const SprPicture& p) {
    const float x = std::max(std::fabs(float(p.origin_x)), std::fabs(float(p.origin_x + p.width)));
    const float y = std::max(std::fabs(float(p.origin_y)), std::fabs(float(p.origin_y - p.height)));
    return std::sqrt(x * x + y * y);
}

std::vector<float> frame_intervals(const SprFrame& frame) {
    if (frame.is_group && frame.intervals.size() == frame.pictures.size() &&
        !frame.intervals.empty()) {
        return frame.intervals;
    }
    std::vector<float> out(std::max<size_t>(frame.pictures.size(), 1));
    for (size_t i = 0; i < out.size(); ++i) out[i] = kDefaultAnimationInterval * float(i + 1);
    return out;
}

}  // namespace

std::shared_ptr<const SpriteModelData> SpriteModelData::build(Spr spr) {
    std::shared_ptr<SpriteModelData> data(new SpriteModelData());
    data->spr_ = std::move(spr);
    data->convert();
    data->link_abi();
    return data;
}

void SpriteModelData::convert() {
    for (const SprFrame& frame : spr_.frames) {
        nqr_sprite_frame f{};
        f.size = sizeof(nqr_sprite_frame);
        f.first_image = static_cast<uint32_t>(images_.size());
        f.num_images = static_cast<uint32_t>(frame.pictures.size());
        for (const SprPicture& picture : frame.pictures) {
            images_.push_back(image_record(picture));
            radius_ = std::max(radius_, corner_radius(picture));
        }
        intervals_.push_back(frame_intervals(frame));
        frames_.push_back(f);
    }
    for (size_t i = 0; i < frames_.size(); ++i) frames_[i].intervals = intervals_[i].data();
}

void SpriteModelData::link_abi() {
    sprite_ = nqr_sprite_model{};
    sprite_.size = sizeof(nqr_sprite_model);
    sprite_.type = static_cast<uint32_t>(spr_.header.type);
    sprite_.num_images = static_cast<uint32_t>(images_.size());
    sprite_.num_frames = static_cast<uint32_t>(frames_.size());
    sprite_.images = images_.empty() ? nullptr : images_.data();
    sprite_.frames = frames_.empty() ? nullptr : frames_.data();
}

}  // namespace nq

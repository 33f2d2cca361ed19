#include "classic/sprite_model_gpu.h"

#include <span>

#include "abi/abi_access.h"
#include "gl/texture_upload.h"

namespace nq::npr::classic {

std::unique_ptr<SpriteModelGpu> SpriteModelGpu::create(gl::ObjectTracker* tracker,
                                                       const nqr_sprite_model& model,
                                                       const uint8_t* palette_rgb,
                                                       std::string& error) {
    if (!has_known_prefix(&model) || !abi_array_usable(model.images, model.num_images)) {
        error = "sprite model or its images of an unknown size";
        return nullptr;
    }
    auto gpu = std::make_unique<SpriteModelGpu>();
    gpu->type_ = model.type;
    gpu->images_.resize(model.num_images);
    std::vector<uint8_t> scratch;
    for (uint32_t i = 0; i < model.num_images; ++i) {
        const nqr_sprite_image& source = abi_element(model.images, i);
        if (!source.pixels || source.width <= 0 || source.height <= 0) continue;
        SpriteImageGpu& image = gpu->images_[i];
        const size_t count = static_cast<size_t>(source.width) * source.height;
        image.texture = gl::create_palette_texture(
            tracker, source.width, source.height, std::span<const uint8_t>(source.pixels, count),
            palette_rgb, {.transparent = gl::Transparent::index255}, gl::kMipmappedClamp, scratch);
        image.width = static_cast<float>(source.width);
        image.height = static_cast<float>(source.height);
        image.origin_x = static_cast<float>(source.origin_x);
        image.origin_y = static_cast<float>(source.origin_y);
    }
    return gpu;
}

const SpriteImageGpu* SpriteModelGpu::image(uint32_t index) const {
    if (index >= images_.size() || !images_[index].texture) return nullptr;
    return &images_[index];
}

}  // namespace nq::npr::classic

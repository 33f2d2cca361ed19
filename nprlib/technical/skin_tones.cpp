#include "technical/skin_tones.h"

#include <algorithm>
#include <cstddef>

#include "abi/abi_access.h"
#include "classic/alias_model_gpu.h"
#include "gl/palette_image.h"

namespace nq::npr::technical {
namespace {

bool is_holey(const nqr_alias_model& model) {
    return (model.flags & classic::kAliasFlagHoley) != 0;
}

size_t pixel_count(const nqr_alias_model& model) {
    return size_t(std::max(model.skin_width, 0)) * size_t(std::max(model.skin_height, 0));
}

// The lit base texture's colour of one (translated) palette index, 0..1.
glm::vec3 base_colour(const uint8_t* palette, uint8_t index) {
    if (gl::is_fullbright_index(index)) return glm::vec3(0.0f);
    const uint8_t* rgb = palette + size_t(index) * 3;
    return glm::vec3(rgb[0], rgb[1], rgb[2]) / 255.0f;
}

}  // namespace

PaletteHistogram count_palette_indices(const nqr_alias_model& model, const uint8_t* pixels) {
    PaletteHistogram counts{};
    if (!pixels) return counts;
    const size_t n = pixel_count(model);
    for (size_t i = 0; i < n; ++i) ++counts[pixels[i]];
    return counts;
}

glm::vec3 SkinSample::kd(int32_t s, int32_t t, float blend) const {
    if (blend <= 0.0f || !pixels || width <= 0 || height <= 0) return average;
    const size_t x = size_t(std::clamp(s, 0, width - 1));
    const size_t y = size_t(std::clamp(t, 0, height - 1));
    const uint8_t index = pixels[y * size_t(width) + x];
    if (holey && index == gl::kTransparentIndex) return average;
    const glm::vec3 texel = base_colour(palette, translation[index]);
    return average + (texel - average) * std::min(blend, 1.0f);
}

void SkinTones::build(const nqr_alias_model& model) {
    images_.clear();
    if (!npr::has_known_prefix(model.skins)) return;
    for (uint32_t s = 0; s < model.num_skins; ++s) {
        const nqr_alias_skin& skin = npr::abi_element(model.skins, s);
        for (uint32_t i = 0; skin.images && i < skin.num_images; ++i) {
            if (skin.images[i]) {
                images_.push_back({skin.images[i], count_palette_indices(model, skin.images[i])});
            }
        }
    }
}

SkinSample SkinTones::sample(const nqr_alias_model& model, const uint8_t* pixels,
                             const nqr_entity& entity, const uint8_t* palette) const {
    for (const Image& image : images_) {
        if (image.pixels == pixels)
            return sample_skin(model, pixels, entity, palette, &image.counts);
    }
    return sample_skin(model, pixels, entity, palette);
}

SkinSample sample_skin(const nqr_alias_model& model, const uint8_t* pixels,
                       const nqr_entity& entity, const uint8_t* palette,
                       const PaletteHistogram* counts) {
    SkinSample out;
    if (!pixels || !palette) return out;
    out.pixels = pixels;
    out.width = model.skin_width;
    out.height = model.skin_height;
    out.palette = palette;
    out.holey = is_holey(model);
    for (int i = 0; i < 256; ++i) out.translation[size_t(i)] = static_cast<uint8_t>(i);
    if (entity.has_translation) {
        out.translation = classic::player_translation(entity.top_color, entity.bottom_color);
    }
    const PaletteHistogram own = counts ? PaletteHistogram{} : count_palette_indices(model, pixels);
    const PaletteHistogram& histogram = counts ? *counts : own;
    glm::dvec3 sum(0.0);
    uint64_t total = 0;
    for (int i = 0; i < 256; ++i) {
        const uint32_t n = histogram[size_t(i)];
        if (n == 0 || (out.holey && i == gl::kTransparentIndex)) continue;
        sum += glm::dvec3(base_colour(palette, out.translation[size_t(i)])) * double(n);
        total += n;
    }
    if (total > 0) out.average = glm::vec3(sum / double(total));
    return out;
}

}  // namespace nq::npr::technical

#include "classic/translated_skins.h"

#include <span>

#include "classic/player_colors.h"
#include "gl/texture_upload.h"

namespace nq::npr::classic {

void TranslatedSkins::init(gl::ObjectTracker* tracker, const uint8_t* palette_rgb) {
    tracker_ = tracker;
    palette_ = palette_rgb;
}

void TranslatedSkins::reset() {
    for (Entry& entry : entries_) entry = Entry{};
    translated_.clear();
    translated_.shrink_to_fit();
    rgba_.clear();
    rgba_.shrink_to_fit();
}

TranslatedSkins::Entry& TranslatedSkins::victim() {
    Entry* oldest = &entries_[0];
    for (Entry& entry : entries_) {
        if (!entry.texture) return entry;
        if (entry.last_used < oldest->last_used) oldest = &entry;
    }
    return *oldest;
}

GLuint TranslatedSkins::get(nqr_model_id model_id, const AliasModelGpu& model, uint32_t skin,
                            uint32_t image, uint8_t top, uint8_t bottom, uint64_t frame_number) {
    top &= 15;
    bottom &= 15;
    for (Entry& entry : entries_) {
        if (entry.texture && entry.model == model_id && entry.skin == skin &&
            entry.image == image && entry.top == top && entry.bottom == bottom) {
            entry.last_used = frame_number;
            return entry.texture.id();
        }
    }
    const uint8_t* pixels = model.skin_pixels(skin, image);
    if (pixels == nullptr) return 0;
    const nqr_alias_model& source = model.model();
    const size_t count = static_cast<size_t>(source.skin_width) * source.skin_height;
    translate_pixels(std::span<const uint8_t>(pixels, count), player_translation(top, bottom),
                     translated_);
    gl::PaletteExpansion expansion{.blacken_fullbrights = true};
    if (model.holey()) expansion.transparent = gl::Transparent::index255;
    Entry& entry = victim();
    entry.texture =
        gl::create_palette_texture(tracker_, source.skin_width, source.skin_height, translated_,
                                   palette_, expansion, gl::kMipmappedRepeat, rgba_);
    entry.model = model_id;
    entry.skin = skin;
    entry.image = image;
    entry.top = top;
    entry.bottom = bottom;
    entry.last_used = frame_number;
    ++uploads_;
    return entry.texture.id();
}

void TranslatedSkins::forget_model(nqr_model_id model_id) {
    for (Entry& entry : entries_) {
        if (entry.model == model_id) entry = Entry{};
    }
}

}  // namespace nq::npr::classic

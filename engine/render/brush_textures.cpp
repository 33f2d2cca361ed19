#include "render/brush_textures.h"

#include <algorithm>

#include "render/texture_animation.h"

namespace nq {

namespace {

bool starts_with_ignoring_case(std::string_view text, std::string_view prefix) {
    if (text.size() < prefix.size()) return false;
    for (size_t i = 0; i < prefix.size(); ++i) {
        const char c = text[i];
        const char lower = (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
        if (lower != prefix[i]) return false;
    }
    return true;
}

void copy_chain(const std::vector<int32_t>& chain, uint32_t& count, int32_t (&out)[10]) {
    count = static_cast<uint32_t>(std::min<size_t>(chain.size(), 10));
    for (uint32_t i = 0; i < count; ++i) out[i] = chain[i];
}

nqr_texture texture_record(const BspTexture& texture, const TextureAnimation& animation) {
    nqr_texture t{};
    t.size = sizeof(nqr_texture);
    t.name = texture.name.c_str();
    t.width = texture.width;
    t.height = texture.height;
    for (int level = 0; level < kBspMipLevels; ++level) {
        const auto& pixels = texture.mips[level].pixels;
        t.mips[level] = pixels.empty() ? nullptr : pixels.data();
    }
    t.flags = texture_flags_for_name(texture.name);
    if (texture.placeholder) t.flags |= NQR_TEXTURE_MISSING;
    copy_chain(animation.frames, t.num_anim_frames, t.anim_frames);
    copy_chain(animation.alternate, t.num_alt_anim_frames, t.alt_anim_frames);
    return t;
}

}  // namespace

uint32_t texture_flags_for_name(std::string_view name) {
    if (starts_with_ignoring_case(name, "sky")) return NQR_TEXTURE_SKY;
    if (!name.empty() && name[0] == '*') return NQR_TEXTURE_LIQUID;
    return 0;
}

BrushTextures build_brush_textures(const Bsp& bsp) {
    std::vector<std::string_view> names;
    names.reserve(bsp.textures.size());
    for (const BspTexture& t : bsp.textures) names.push_back(t.name);
    TextureAnimations animations = resolve_texture_animations(names);

    BrushTextures out;
    out.warnings = std::move(animations.warnings);
    out.textures.reserve(bsp.textures.size());
    for (size_t i = 0; i < bsp.textures.size(); ++i) {
        out.textures.push_back(texture_record(bsp.textures[i], animations.per_texture[i]));
    }
    return out;
}

}  // namespace nq

#include "gl/texture_upload.h"

namespace nq::npr::gl {

void apply_sampling(GLenum target, const Sampling& sampling) {
    glTexParameteri(target, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(sampling.min_filter));
    glTexParameteri(target, GL_TEXTURE_MAG_FILTER, static_cast<GLint>(sampling.mag_filter));
    glTexParameteri(target, GL_TEXTURE_WRAP_S, static_cast<GLint>(sampling.wrap));
    glTexParameteri(target, GL_TEXTURE_WRAP_T, static_cast<GLint>(sampling.wrap));
}

Texture create_rgba8_texture(ObjectTracker* tracker, int width, int height,
                             std::span<const uint8_t> rgba, const Sampling& sampling) {
    Texture texture = Texture::create(tracker);
    glBindTexture(GL_TEXTURE_2D, texture.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 rgba.data());
    apply_sampling(GL_TEXTURE_2D, sampling);
    if (sampling.mipmaps) glGenerateMipmap(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_2D, 0);
    return texture;
}

Texture create_solid_texture(ObjectTracker* tracker, uint8_t r, uint8_t g, uint8_t b, uint8_t a) {
    const uint8_t texel[4] = {r, g, b, a};
    return create_rgba8_texture(tracker, 1, 1, texel, kNearestClamp);
}

Texture create_palette_texture(ObjectTracker* tracker, int width, int height,
                               std::span<const uint8_t> pixels, const uint8_t* palette_rgb,
                               PaletteExpansion expansion, const Sampling& sampling,
                               std::vector<uint8_t>& scratch, const RgbaFilter* filter) {
    expand_palette_texels(width, height, pixels, palette_rgb, expansion, scratch, filter);
    return create_rgba8_texture(tracker, width, height, scratch, sampling);
}

void expand_palette_texels(int width, int height, std::span<const uint8_t> pixels,
                           const uint8_t* palette_rgb, PaletteExpansion expansion,
                           std::vector<uint8_t>& rgba, const RgbaFilter* filter) {
    expand_palette_image(pixels, palette_rgb, expansion, rgba);
    if (expansion.transparent != Transparent::none) {
        bleed_colour_into_transparent_texels(rgba, width, height);
    }
    if (filter && *filter) (*filter)(width, height, rgba);
}

Texture create_fullbright_texture(ObjectTracker* tracker, int width, int height,
                                  std::span<const uint8_t> pixels, const uint8_t* palette_rgb,
                                  const Sampling& sampling, std::vector<uint8_t>& scratch) {
    if (!has_fullbright_pixels(pixels)) return {};
    extract_fullbright_mask(pixels, palette_rgb, scratch);
    return create_rgba8_texture(tracker, width, height, scratch, sampling);
}

}  // namespace nq::npr::gl

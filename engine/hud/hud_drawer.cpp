#include "hud/hud_drawer.h"

#include "draw2d/rgba_texture.h"

namespace nq {

Result<HudDrawer> HudDrawer::create() {
    Result<QuadRenderer> renderer = QuadRenderer::create(kHudQuadCapacity);
    if (!renderer) return renderer.error();
    return HudDrawer(std::move(*renderer));
}

void HudDrawer::set_pictures(HudPictures pictures) {
    pictures_ = std::move(pictures);
    const RgbaImage& image = pictures_.atlas_image();
    if (image.empty()) {
        atlas_.reset();
        return;
    }
    if (!atlas_) atlas_ = npr::gl::Texture::create(nullptr);
    // Filtered like QuakeSpasm's pictures, so fractional scales (its 1.6) look the same; the
    // glyphs stay texel-exact (QuadBatch::glyph).
    upload_rgba_texture(atlas_.id(), image.width, image.height, image.rgba.data(),
                        TextureFilter::Linear);
}

void HudDrawer::draw(const ClientState& client, const ScreenBlend& blend, const HudFrame& frame,
                     bool with_hud) {
    drawn_ = false;
    const int width = frame.screen.width, height = frame.screen.height;
    Colour tint{unit_to_byte(blend.r), unit_to_byte(blend.g), unit_to_byte(blend.b),
                unit_to_byte(blend.a)};
    bool bars = with_hud && atlas_ && hud_has_content(client, frame, pictures_);
    if ((tint.a == 0 && !bars) || width <= 0 || height <= 0) return;

    drawn_ = true;
    QuadRenderer::Pass pass(renderer_, width, height);
    // The tint is a solid quad: it samples nothing, so it shares the batch with the pictures.
    if (atlas_) pass.use_texture(atlas_.id());
    if (tint.a > 0) {
        pass.batch().solid(0, 0, static_cast<float>(width), static_cast<float>(height), tint);
    }
    if (bars) build_hud(client, frame, pictures_, pass.batch());
}

}  // namespace nq

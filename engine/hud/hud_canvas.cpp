#include "hud/hud_canvas.h"

#include <algorithm>
#include <cmath>

namespace nq {
namespace {

constexpr float kMaxCrosshairScale = 10.0f;

// QuakeSpasm's CLAMP(1, requested, largest): `largest` wins when it is below 1, so a screen
// narrower than the layout shrinks it rather than cutting it off.
float clamp_scale(float requested, float largest) {
    if (!(requested >= 1.0f)) requested = 1.0f;  // also NaN
    return requested > largest ? largest : requested;
}

}  // namespace

HudCanvas::HudCanvas(QuadBatch& batch, const HudPictures& pictures, float origin_x, float origin_y,
                     float scale)
    : batch_(batch),
      pictures_(pictures),
      origin_x_(std::floor(origin_x)),
      origin_y_(std::floor(origin_y)),
      scale_(scale) {}

float HudCanvas::status_bar_scale(const HudScreen& screen) {
    return clamp_scale(screen.requested_scale, static_cast<float>(screen.width) / kVirtualWidth);
}

HudCanvas HudCanvas::status_bar(QuadBatch& batch, const HudPictures& pictures,
                                const HudScreen& screen, bool deathmatch) {
    float scale = status_bar_scale(screen);
    float left = deathmatch ? 0.0f : (static_cast<float>(screen.width) - kVirtualWidth * scale) / 2;
    float top = static_cast<float>(screen.height) - kStatusBarCanvasHeight * scale;
    return HudCanvas(batch, pictures, left, top, scale);
}

HudCanvas::Placement HudCanvas::menu_placement(const HudScreen& screen) {
    float fits = std::min(static_cast<float>(screen.width) / kVirtualWidth,
                          static_cast<float>(screen.height) / kMenuHeight);
    float scale = clamp_scale(screen.requested_scale, fits);
    float left = (static_cast<float>(screen.width) - kVirtualWidth * scale) / 2;
    float top = (static_cast<float>(screen.height) - kMenuHeight * scale) / 2;
    return {std::floor(left), std::floor(top), scale};
}

HudCanvas HudCanvas::menu(QuadBatch& batch, const HudPictures& pictures, const HudScreen& screen) {
    const Placement at = menu_placement(screen);
    return HudCanvas(batch, pictures, at.left, at.top, at.scale);
}

HudCanvas HudCanvas::crosshair(QuadBatch& batch, const HudPictures& pictures,
                               const HudScreen& screen) {
    float scale = clamp_scale(screen.requested_scale, kMaxCrosshairScale);
    return HudCanvas(batch, pictures, static_cast<float>(screen.width / 2),
                     static_cast<float>(screen.height / 2), scale);
}

void HudCanvas::picture(PictureId id, float x, float y, uint8_t alpha) const {
    const AtlasPicture* picture = pictures_.find(id);
    if (!picture) return;
    batch_.image(screen_x(x), screen_y(y), static_cast<float>(picture->width) * scale_,
                 static_cast<float>(picture->height) * scale_, Colour{255, 255, 255, alpha},
                 picture->region);
}

int HudCanvas::picture_width(PictureId id) const {
    const AtlasPicture* picture = pictures_.find(id);
    return picture ? picture->width : 0;
}

void HudCanvas::character(float x, float y, uint8_t glyph) const {
    const AtlasPicture* font = pictures_.find(pictures_.ids().conchars);
    if (!font || glyph == ' ') return;
    batch_.glyph(glyph, screen_x(x), screen_y(y), kCharacterSize * scale_, Colour{}, font->region);
}

void HudCanvas::text(float x, float y, std::string_view text) const {
    for (char c : text) {
        character(x, y, static_cast<uint8_t>(c));
        x += kCharacterSize;
    }
}

void HudCanvas::fill(float x, float y, float width, float height, uint8_t index) const {
    Rgb colour = pictures_.palette_colour(index);
    batch_.solid(screen_x(x), screen_y(y), width * scale_, height * scale_,
                 Colour{colour.r, colour.g, colour.b, 255});
}

}  // namespace nq

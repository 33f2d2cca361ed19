// Quake's 2D canvases: its overlays are laid out in virtual pixels of a 320-wide screen, and a
// canvas places those on the real screen at an origin and a scale, as QuakeSpasm's
// GL_SetCanvas does:
//   status bar  320 x 48, bottom-centred (deathmatch: the whole width, from the left);
//   menu        320 x 200, centred (the intermission and ranking screens);
//   crosshair   its origin at the centre of the screen.
// The scale is `scr_sbarscale` limited to what fits (never below 1 unless the screen is
// narrower than 320 pixels).
#pragma once

#include <cstdint>
#include <string_view>

#include "draw2d/quad_batch.h"
#include "formats/palette.h"
#include "hud/hud_pictures.h"

namespace nq {

inline constexpr int kVirtualWidth = 320;
inline constexpr int kStatusBarHeight = 24;        // one bar: sbar, ibar or scorebar
inline constexpr int kStatusBarCanvasHeight = 48;  // the inventory above the status bar
inline constexpr float kInventoryTop = 0;          // rows of the status bar canvas
inline constexpr float kStatusBarTop = kStatusBarHeight;
inline constexpr int kMenuHeight = 200;
inline constexpr int kCharacterSize = 8;  // conchars glyphs, in virtual pixels
// `viewsize` thresholds: below 110 the inventory shows, below 120 the status bar.
inline constexpr float kViewsizeNoInventory = 110;
inline constexpr float kViewsizeNoBars = 120;

struct HudScreen {
    int width = 0;  // pixels
    int height = 0;
    float requested_scale = 1;  // scr_sbarscale
};

class HudCanvas {
  public:
    HudCanvas(QuadBatch& batch, const HudPictures& pictures, float origin_x, float origin_y,
              float scale);

    static HudCanvas status_bar(QuadBatch& batch, const HudPictures& pictures,
                                const HudScreen& screen, bool deathmatch);
    static HudCanvas menu(QuadBatch& batch, const HudPictures& pictures, const HudScreen& screen);
    // Where the menu canvas lies on `screen`: its top-left corner in pixels and its scale.
    struct Placement {
        float left, top, scale;
    };
    static Placement menu_placement(const HudScreen& screen);
    static HudCanvas crosshair(QuadBatch& batch, const HudPictures& pictures,
                               const HudScreen& screen);
    // The status bar canvas's scale on `screen` (its bars are 24 * scale pixels tall).
    static float status_bar_scale(const HudScreen& screen);

    // Picture `id` with its top-left corner at (x, y), its pixels' alpha times alpha / 255.
    // Nothing when the game data lacks it.
    void picture(PictureId id, float x, float y, uint8_t alpha = 255) const;
    int picture_width(PictureId id) const;  // 0 when missing
    // Conchars glyph `glyph` (128..255: the alternate colours) as an 8x8 cell at (x, y).
    void character(float x, float y, uint8_t glyph) const;
    // One character per byte from (x, y); spaces advance without drawing.
    void text(float x, float y, std::string_view text) const;
    // A solid rectangle of palette colour `index`.
    void fill(float x, float y, float width, float height, uint8_t index) const;

    const HudPictures& pictures() const { return pictures_; }
    float scale() const { return scale_; }
    // Where virtual (x, y) lands on the screen, in pixels.
    float screen_x(float x) const { return origin_x_ + x * scale_; }
    float screen_y(float y) const { return origin_y_ + y * scale_; }

  private:
    QuadBatch& batch_;
    const HudPictures& pictures_;
    float origin_x_, origin_y_, scale_;
};

}  // namespace nq

#include "hud/hud_scene.h"

#include <cstdio>
#include <cstring>

#include "hud/intermission.h"
#include "hud/scoreboard.h"
#include "hud/status_bar.h"

namespace nq {
namespace {

constexpr uint8_t kCrosshairGlyph = '+';
constexpr float kCrosshairOffset = -kCharacterSize / 2.0f;  // the glyph's centre on the centre

void build_status_bar_canvas(const ClientState& client, const HudFrame& frame,
                             const HudPictures& pictures, QuadBatch& batch) {
    const HudSettings& settings = frame.settings;
    bool deathmatch = client.level().game_type == kGameTypeDeathmatch;
    HudCanvas canvas = HudCanvas::status_bar(batch, pictures, frame.screen, deathmatch);
    uint8_t alpha = unit_to_byte(settings.bar_alpha);

    if (settings.viewsize < kViewsizeNoInventory) {
        draw_inventory(canvas, client, alpha);
        if (client.level().max_clients != 1) draw_inventory_frags(canvas, client);
    }
    bool dead = client.player().stats[kStatHealth] <= 0;
    if (settings.show_scores || dead) {
        canvas.picture(pictures.ids().scorebar, 0, kStatusBarTop, alpha);
        draw_solo_scoreboard(canvas, client, frame.real_time);
        if (deathmatch) {
            draw_deathmatch_ranking(HudCanvas::menu(batch, pictures, frame.screen), client);
        }
    } else if (settings.viewsize < kViewsizeNoBars) {
        draw_status_bar(canvas, client, alpha);
    }
    if (deathmatch) {
        draw_mini_deathmatch_overlay(canvas, client, settings.viewsize, frame.screen.width);
    }
}

// QuakeSpasm's "%4.0f fps", at the top right on the status bar's scale.
void draw_fps(const HudFrame& frame, const HudPictures& pictures, QuadBatch& batch) {
    char text[16];
    std::snprintf(text, sizeof text, "%4.0f fps", double(frame.fps));
    const float scale = HudCanvas::status_bar_scale(frame.screen);
    const float width = float(std::strlen(text)) * kCharacterSize;
    HudCanvas canvas(batch, pictures, float(frame.screen.width) - (width + 8) * scale, 0, scale);
    canvas.text(0, 4, text);
}

}  // namespace

bool hud_has_content(const ClientState& client, const HudFrame& frame,
                     const HudPictures& pictures) {
    if (pictures.empty() || frame.screen.width <= 0 || frame.screen.height <= 0) return false;
    switch (client.intermission()) {
        case Intermission::Intermission:
        case Intermission::Finale:
            return true;
        case Intermission::Cutscene:
            return frame.settings.crosshair;
        case Intermission::None:
            break;
    }
    // Even at viewsize 120 the scorebar shows while dead or holding +showscores.
    return frame.settings.crosshair || frame.settings.show_fps ||
           frame.settings.viewsize < kViewsizeNoBars || frame.settings.show_scores ||
           client.player().stats[kStatHealth] <= 0;
}

void build_hud(const ClientState& client, const HudFrame& frame, const HudPictures& pictures,
               QuadBatch& batch) {
    if (!hud_has_content(client, frame, pictures)) return;
    switch (client.intermission()) {
        case Intermission::Intermission:
            draw_intermission(HudCanvas::menu(batch, pictures, frame.screen), client);
            return;
        case Intermission::Finale:
            draw_finale(HudCanvas::menu(batch, pictures, frame.screen));
            return;
        case Intermission::Cutscene:
        case Intermission::None:
            break;
    }
    if (frame.settings.show_fps) draw_fps(frame, pictures, batch);
    if (frame.settings.crosshair) {
        HudCanvas::crosshair(batch, pictures, frame.screen)
            .character(kCrosshairOffset, kCrosshairOffset, kCrosshairGlyph);
    }
    if (client.intermission() == Intermission::None) {
        build_status_bar_canvas(client, frame, pictures, batch);
    }
}

}  // namespace nq

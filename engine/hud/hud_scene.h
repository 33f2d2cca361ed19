// What Quake draws over the 3D view each frame, before the console, as quads (no GL here, so
// the layout can be tested on its own): the 2D part of QuakeSpasm's screen update.
//
//   intermission  the intermission screen (intermission.h), nothing else
//   finale        the finale picture
//   otherwise     the crosshair, then -- except during a cutscene -- the status bar canvas:
//                 the inventory (viewsize < 110); the scorebar while dead or holding
//                 +showscores (whatever the viewsize, as in Quake), else the status bar
//                 (viewsize < 120); in deathmatch also the ranking with the scorebar and the
//                 mini scoreboard beside the bars.
//
// The 3D view is never shrunk for the bars: they are drawn over it, as QuakeSpasm draws its
// translucent bar (scr_sbaralpha < 1, 0.75 by default).
#pragma once

#include "client/client_state.h"
#include "draw2d/quad_batch.h"
#include "hud/hud_canvas.h"
#include "hud/hud_pictures.h"

namespace nq {

struct HudSettings {
    float viewsize = 100;      // `viewsize`
    float bar_alpha = 0.75f;   // `scr_sbaralpha`, 0..1
    bool crosshair = false;    // `crosshair`
    bool show_scores = false;  // +showscores held
    bool show_fps = false;     // `scr_showfps`
};

struct HudFrame {
    HudScreen screen;
    HudSettings settings;
    double real_time = 0;  // seconds; scrolls long level names
    float fps = 0;         // frames per second over the last second (scr_showfps)
};

// Whether build_hud() would emit anything for this client and these settings.
bool hud_has_content(const ClientState& client, const HudFrame& frame, const HudPictures& pictures);
void build_hud(const ClientState& client, const HudFrame& frame, const HudPictures& pictures,
               QuadBatch& batch);

}  // namespace nq

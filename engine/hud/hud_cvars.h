// The cvars of the engine-drawn screen overlays, registered with descriptions through the
// host's CvarRegistry:
//   viewsize       100   100: status bar and inventory, 110: status bar only, 120: neither
//                        (30..120 accepted, as in Quake; below 100 counts as 100)
//   scr_sbarscale  1     status bar, intermission and crosshair scale (limited to what fits)
//   scr_sbaralpha  0.75  opacity of the status, inventory and score bar backgrounds
//   crosshair      0     1: a '+' at the centre of the screen
//   scr_drawhud    1     0: none of the above, nor scoreboards or the intermission screen (the
//                        renderer's picture alone, for screenshots; Quake has no such switch)
//   gl_polyblend   1     0: no full-screen tints (damage, pickups, powerups, liquids)
//   scr_showfps    0     1: frames per second at the top right, over the last second
#pragma once

#include "host/cvar_registry.h"

namespace nq {

struct HudCvars {
    const Cvar* viewsize = nullptr;
    const Cvar* bar_scale = nullptr;
    const Cvar* bar_alpha = nullptr;
    const Cvar* crosshair = nullptr;
    const Cvar* draw_hud = nullptr;
    const Cvar* polyblend = nullptr;
    const Cvar* show_fps = nullptr;
};

// Registers (or re-registers) the cvars. Never fails: the specs are valid.
HudCvars register_hud_cvars(CvarRegistry& cvars);

}  // namespace nq

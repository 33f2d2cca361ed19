#include "hud/hud_cvars.h"

#include <cassert>

namespace nq {
namespace {

const Cvar* register_numeric(CvarRegistry& cvars, const char* name, const char* value,
                             uint32_t flags, float min, float max, const char* description) {
    const Cvar* cvar = cvars.register_cvar(CvarSpec{name, value, flags, description, min, max});
    assert(cvar && "hud cvar specs are valid");
    return cvar;
}

}  // namespace

HudCvars register_hud_cvars(CvarRegistry& cvars) {
    HudCvars out;
    out.viewsize = register_numeric(
        cvars, "viewsize", "100", kCvarArchive, 30.0f, 120.0f,
        "screen size: 100 status bar and inventory, 110 status bar only, 120 neither");
    out.bar_scale = register_numeric(
        cvars, "scr_sbarscale", "1", kCvarArchive, 1.0f, 16.0f,
        "status bar, intermission and crosshair scale (limited to what fits the screen)");
    out.bar_alpha = register_numeric(cvars, "scr_sbaralpha", "0.75", kCvarArchive, 0.0f, 1.0f,
                                     "opacity of the status bar's background pictures");
    out.crosshair = register_numeric(cvars, "crosshair", "0", kCvarArchive, 0.0f, 1.0f,
                                     "1: draw a '+' at the centre of the screen");
    out.draw_hud = register_numeric(
        cvars, "scr_drawhud", "1", 0, 0.0f, 1.0f,
        "0: no status bar, scoreboard, intermission screen or crosshair (the renderer alone)");
    out.polyblend =
        register_numeric(cvars, "gl_polyblend", "1", 0, 0.0f, 1.0f,
                         "tint the screen for damage, pickups, powerups and liquids (0: never)");
    out.show_fps = register_numeric(cvars, "scr_showfps", "0", kCvarArchive, 0.0f, 1.0f,
                                    "1: frames per second at the top right of the screen");
    return out;
}

}  // namespace nq

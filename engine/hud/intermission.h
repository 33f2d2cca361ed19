// The end-of-level screens on the menu canvas (hud_canvas.h: 320 x 200, centred):
//   intermission  single player: gfx/complete.lmp and gfx/inter.lmp, with the time taken
//                 (m:ss), secrets found / total and monsters killed / total in big digits;
//                 deathmatch: the ranking (scoreboard.h);
//   finale        the episode's end: gfx/finale.lmp (its text is the console's centre print).
// Whatever pictures the game lacks are left out; the numbers are drawn regardless.
#pragma once

#include "client/client_state.h"
#include "hud/hud_canvas.h"

namespace nq {

void draw_intermission(const HudCanvas& menu, const ClientState& client);
void draw_finale(const HudCanvas& menu);

}  // namespace nq

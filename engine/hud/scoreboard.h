// The scoreboards, as Quake lays them out:
//   solo      on the scorebar in place of the status bar while dead (or while +showscores
//             is held): kills, secrets and the level's name;
//   frags     in multiplayer, the four best players' frags on the inventory bar, in their
//             colours, with brackets around the viewer;
//   mini      in deathmatch, on screens at least 512 virtual pixels wide, a few players
//             around the viewer to the right of the status bar;
//   ranking   in deathmatch, the full list on the menu canvas (at the intermission, or while
//             dead or holding +showscores), under gfx/ranking.lmp when the game has it.
// Players are listed by frags, most first; players without a name are left out.
#pragma once

#include <array>
#include <cstddef>

#include "client/client_state.h"
#include "hud/hud_canvas.h"

namespace nq {

struct FragOrder {
    std::array<int, kMaxScoreboard> clients{};  // scoreboard slots, most frags first
    size_t count = 0;
};

FragOrder sort_frags(const ClientState& client);

void draw_solo_scoreboard(const HudCanvas& status_bar, const ClientState& client, double real_time);
void draw_inventory_frags(const HudCanvas& status_bar, const ClientState& client);
void draw_mini_deathmatch_overlay(const HudCanvas& status_bar, const ClientState& client,
                                  float viewsize, int screen_width);
void draw_deathmatch_ranking(const HudCanvas& menu, const ClientState& client);

}  // namespace nq

// A player's MOVETYPE_WALK movement through the world (sv_phys.c's SV_WalkMove): slide along what
// it hits, climb steps up to sv_stepsize, wriggle free of hull-precision snags, slow down along
// walls it faces; and the rescue of players found stuck in solid (SV_CheckStuck).
#pragma once

#include <cstdint>

#include "server/game_state.h"

namespace nq::server {
class ServerHost;
}

namespace nq::server::physics {

// SV_CheckStuck: a player inside solid goes back to its last good origin (oldorigin) or the
// nearest free spot a little around and above; a free player's origin becomes the good one.
void check_stuck(GameState& game, uint32_t edict, ServerHost* host);

// SV_WalkMove: the player's move for this frame, stepping up when a wall blocks it.
void player_walk_move(GameState& game, uint32_t edict);

}  // namespace nq::server::physics

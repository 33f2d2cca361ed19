// How monsters walk (Quake's sv_move.c), for the walkmove, movetogoal, droptofloor and changeyaw
// builtins: a step is a move of a few units that may climb or descend sv_stepsize, must keep
// the monster's corners over ground, and never walks it off a ledge; flyers and swimmers drift
// toward their enemy's height instead. Chasing picks directions with the server's random numbers.
#pragma once

#include <cstdint>

#include "server/game_state.h"
#include "server/random.h"

namespace nq::server {

// PF_walkmove: moves `edict` `dist` units toward `yaw` degrees if the step is allowed; only
// monsters on the ground, flying or swimming move. `relink` also touches triggers on the way.
bool walk_move(GameState& game, uint32_t edict, float yaw, float dist, bool relink);

// SV_MoveToGoal: one step of the chase toward the edict's goalentity, turning toward ideal_yaw
// and, when blocked (or one time in four), choosing a new direction.
void move_to_goal(GameState& game, uint32_t edict, float dist, GameRandom& random);

// PF_droptofloor: puts the edict on the floor up to 256 units below. False when there is no
// floor that close or it starts inside solid.
bool drop_to_floor(GameState& game, uint32_t edict);

// PF_changeyaw: turns angles' yaw toward ideal_yaw by at most yaw_speed degrees.
void change_yaw(GameState& game, uint32_t edict);

// SV_CheckBottom: whether the edict's box stands on ground at its four corners (all solid just
// below, or no corner more than a step below the middle).
bool check_bottom(GameState& game, uint32_t edict);

}  // namespace nq::server

// A player's command turned into movement (Quake's sv_user.c): the view angles and buttons a
// clc_move carries, then once a frame the player's body angles and the velocity the command asks
// for — ground friction (more at ledges) and acceleration, a little air control, swimming,
// noclip and fly. Jumping is QuakeC's (PlayerJump on button2); the move itself is physics.h's.
#pragma once

#include <cstdint>

#include "server/game_state.h"

namespace nq::server {

// What SV_ReadClientMove stores in the player's edict from each command received: v_angle,
// button0 (attack), button2 (jump) and a nonzero impulse.
void apply_user_cmd(GameState& game, uint32_t edict, const UserCmd& cmd);

// SV_ClientThink: once a frame, before run_physics, with the latest command. Sets the body's
// angles from v_angle (a third of the pitch, roll from sideways speed) unless QuakeC fixed them,
// decays punchangle, and changes velocity. Players with MOVETYPE_NONE or no health do not move.
void client_think(GameState& game, uint32_t edict, const UserCmd& cmd);

// V_CalcRoll with Quake's cl_rollangle 2 and cl_rollspeed 200: the roll of a body moving at
// `velocity` while facing `angles`.
float calc_roll(const vm::Vec3f& angles, const vm::Vec3f& velocity);

}  // namespace nq::server

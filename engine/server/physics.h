// One server frame of Quake's physics (sv_phys.c's SV_Physics): QuakeC's StartFrame, then every
// edict in turn by its movetype — players (PlayerPreThink, their move, PlayerPostThink), pushers,
// fixed things, noclippers, stepping monsters, tossed, bouncing and flying things — with their
// think functions when nextthink falls within the frame.
//
// The caller owns the clock: GameState::time is the time of the frame being run and
// GameState::frame_time how far it advances; the caller adds frame_time to time afterwards.
// Player commands (player_move.h) run before this, as Quake's SV_RunClients does.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "server/game_state.h"
#include "server/physics_push.h"

namespace nq::server {

class ServerHost;

// What physics keeps between frames: where its console messages go, and memory it reuses so
// that running a frame allocates nothing once the first pusher has moved.
struct PhysicsContext {
    ServerHost* host = nullptr;  // "Got a NaN velocity", "Unstuck."; may be null
    std::vector<physics::MovedEdict> moved;
};

// Runs one frame. clients_spawned[i] != 0 when the player of edict i + 1 is in the game; client
// edicts without an entry (or with 0) are skipped. False when QuakeC failed: the VM holds the
// error, the frame stopped where it happened, and the server should end the level.
bool run_physics(GameState& game, std::span<const uint8_t> clients_spawned,
                 PhysicsContext& context);

}  // namespace nq::server

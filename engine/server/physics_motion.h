// The movement primitives Quake's server physics is built from (sv_phys.c): thinking, touching,
// gravity, velocity limits, sliding along clip planes, pushing an entity through the world and
// noticing when it enters or leaves water. The frame loop (physics.h), the player's walk and the
// pushers use them; they work on one GameState and keep no state of their own.
//
// QuakeC errors: every call into QuakeC may fail; the VM then refuses every later call, so these
// functions simply stop calling it and the frame loop ends the frame when it sees the error.
#pragma once

#include <cstdint>
#include <string_view>

#include "server/game_state.h"
#include "server/world.h"

namespace nq::server {
class ServerHost;
}

namespace nq::server::physics {

using vm::Vec3f;

inline constexpr float kStopEpsilon = 0.1f;  // velocity components smaller than this stop
inline constexpr int kMaxClipPlanes = 5;

// fly_move's result bits, as Quake's SV_FlyMove returns them.
enum Blocked : int {
    kBlockedFloor = 1,    // hit a surface steeper than 45 degrees up
    kBlockedStep = 2,     // hit a vertical wall (a step, perhaps)
    kBlockedTrapped = 7,  // no direction left to slide in
};

// ---- field shorthands ----
int flags(const GameState& game, uint32_t edict);
void set_flags(GameState& game, uint32_t edict, int flags);
// The edict an entity field names; world (0) when it names none.
uint32_t edict_field(const GameState& game, uint32_t edict, uint32_t field);
void set_edict_field(GameState& game, uint32_t edict, uint32_t field, uint32_t target);
int movetype(const GameState& game, uint32_t edict);
int solid(const GameState& game, uint32_t edict);

// ---- QuakeC ----
// Runs `function` with self and other set; false when QuakeC failed.
bool call_qc(GameState& game, int32_t function, uint32_t self, uint32_t other);
// SV_RunThink: runs the think function when nextthink falls before the end of this frame. False
// when the entity was removed (or QuakeC failed), so its physics stops.
bool run_think(GameState& game, uint32_t edict);
// SV_Impact: both entities' touch functions, restoring self and other afterwards.
void impact(GameState& game, uint32_t e1, uint32_t e2);
void start_sound(GameState& game, uint32_t edict, std::string_view sample);

// ---- motion ----
// SV_CheckVelocity: NaN components become 0 (with a console message), speed per axis is capped.
void check_velocity(GameState& game, uint32_t edict, ServerHost* host);
// SV_AddGravity: the entity's own `gravity` factor when the progs has that field and it is set.
void add_gravity(GameState& game, uint32_t edict);
// SV_ClipVelocity: `in` with its part into the plane removed (times overbounce); returns the
// Blocked bits the normal stands for.
int clip_velocity(const Vec3f& in, const Vec3f& normal, Vec3f& out, float overbounce);
// SV_FlyMove: moves for `time` seconds, sliding along up to kMaxClipPlanes planes and calling
// touch functions. `step_trace` receives the last wall hit (for the player's wall friction).
int fly_move(GameState& game, uint32_t edict, float time, MoveTrace* step_trace);
// SV_PushEntity: moves by `push` or up to what blocks it, relinks, touches what it hit.
MoveTrace push_entity(GameState& game, uint32_t edict, const Vec3f& push);
// SV_CheckWaterTransition: watertype/waterlevel of tossed and stepping entities, with a splash.
void check_water_transition(GameState& game, uint32_t edict);
// SV_CheckWater: how deep a player stands in liquid (0..3); true when 2 or more.
bool check_water(GameState& game, uint32_t edict);

}  // namespace nq::server::physics

// Quake's pushers (MOVETYPE_PUSH: doors, platforms, trains): they move on their own clock
// (ltime), carry what stands on them, shove what they run into, and when something cannot be
// shoved they stop, put everything back and call their `blocked` function.
#pragma once

#include <cstdint>
#include <vector>

#include "server/game_state.h"
#include "vm/vm.h"

namespace nq::server::physics {

// Where a shoved entity was before the push, to put it back when the push fails.
struct MovedEdict {
    uint32_t edict = 0;
    vm::Vec3f from{};
};

// SV_Physics_Pusher: moves the pusher for this frame (or up to its nextthink) and runs its think
// when that falls within the time it moved. `moved` is scratch memory reused across frames.
void physics_pusher(GameState& game, uint32_t pusher, std::vector<MovedEdict>& moved);

// SV_PushMove: moves the pusher by velocity * move_time, shoving what is in the way.
void push_move(GameState& game, uint32_t pusher, float move_time, std::vector<MovedEdict>& moved);

}  // namespace nq::server::physics

#include "server/physics_push.h"

#include "server/physics_motion.h"
#include "server/qmath.h"
#include "server/world.h"

namespace nq::server::physics {

namespace {

using vm::Vec3f;

struct Box {
    Vec3f mins, maxs;
};

// Entities a pusher never moves: other pushers, fixed and noclipping things.
bool never_pushed(const GameState& game, uint32_t edict) {
    const int type = movetype(game, edict);
    return type == qc::kMovePush || type == qc::kMoveNone || type == qc::kMoveNoclip;
}

bool rides_on(const GameState& game, uint32_t edict, uint32_t pusher) {
    return (flags(game, edict) & qc::kFlOnGround) &&
           edict_field(game, edict, game.f().groundentity) == pusher;
}

// Whether `edict` is in the pusher's way: its box overlaps where the pusher moved to and it is
// stuck there. Riders are always moved.
bool must_move(GameState& game, uint32_t edict, uint32_t pusher, const Box& swept) {
    if (rides_on(game, edict, pusher)) return true;
    const Vec3f absmin = game.vm.field_vector(edict, game.f().absmin);
    const Vec3f absmax = game.vm.field_vector(edict, game.f().absmax);
    for (int i = 0; i < 3; ++i) {
        if (absmin[i] >= swept.maxs[i] || absmax[i] <= swept.mins[i]) return false;
    }
    return game.world.test_entity_position(edict).has_value();
}

// Shoves `edict` along with the pusher, the pusher itself out of the way (only solid pushers
// shove: a non-solid one would otherwise turn solid).
void shove(GameState& game, uint32_t edict, uint32_t pusher, const Vec3f& move) {
    const float pusher_solid = game.vm.field_float(pusher, game.f().solid);
    const int s = int(pusher_solid);
    if (s != qc::kSolidBsp && s != qc::kSolidBbox && s != qc::kSolidSlideBox) return;
    game.vm.set_field_float(pusher, game.f().solid, float(qc::kSolidNot));
    push_entity(game, edict, move);
    game.vm.set_field_float(pusher, game.f().solid, pusher_solid);
}

// The push failed against `blocker`: everything goes back where it was and the pusher's
// `blocked` function decides what happens (crush, reverse).
void undo_push(GameState& game, uint32_t pusher, uint32_t blocker, const Vec3f& pusher_from,
               float move_time, const std::vector<MovedEdict>& moved) {
    vm::Vm& vm = game.vm;
    const FieldOffsets& f = game.f();
    vm.set_field_vector(blocker, f.origin, moved.back().from);
    game.world.link(blocker, true);
    vm.set_field_vector(pusher, f.origin, pusher_from);
    game.world.link(pusher, false);
    vm.set_field_float(pusher, f.ltime, vm.field_float(pusher, f.ltime) - move_time);
    if (const int32_t blocked = vm.field_int(pusher, f.blocked)) {
        call_qc(game, blocked, pusher, blocker);
    }
    for (const MovedEdict& m : moved) {
        vm.set_field_vector(m.edict, f.origin, m.from);
        game.world.link(m.edict, false);
    }
}

}  // namespace

void push_move(GameState& game, uint32_t pusher, float move_time, std::vector<MovedEdict>& moved) {
    vm::Vm& vm = game.vm;
    const FieldOffsets& f = game.f();
    const Vec3f velocity = vm.field_vector(pusher, f.velocity);
    if (velocity[0] == 0 && velocity[1] == 0 && velocity[2] == 0) {
        vm.set_field_float(pusher, f.ltime, vm.field_float(pusher, f.ltime) + move_time);
        return;
    }
    const Vec3f move = vscale(velocity, move_time);
    const Box swept = {vadd(vm.field_vector(pusher, f.absmin), move),
                       vadd(vm.field_vector(pusher, f.absmax), move)};
    const Vec3f pusher_from = vm.field_vector(pusher, f.origin);
    vm.set_field_vector(pusher, f.origin, vadd(pusher_from, move));
    vm.set_field_float(pusher, f.ltime, vm.field_float(pusher, f.ltime) + move_time);
    game.world.link(pusher, false);

    if (moved.capacity() < vm.max_edicts()) moved.reserve(vm.max_edicts());
    moved.clear();
    for (uint32_t e = 1; e < vm.num_edicts(); ++e) {
        if (game.edicts.is_free(e) || never_pushed(game, e)) continue;
        if (!must_move(game, e, pusher, swept)) continue;
        // Non-players lose their footing; they fall again after the ride.
        if (movetype(game, e) != qc::kMoveWalk) {
            set_flags(game, e, flags(game, e) & ~qc::kFlOnGround);
        }
        moved.push_back({e, vm.field_vector(e, f.origin)});
        shove(game, e, pusher, move);
        if (!game.world.test_entity_position(e)) continue;
        // Still stuck in the pusher. Points and corpses do not block it.
        if (vm.field_vector(e, f.mins)[0] == vm.field_vector(e, f.maxs)[0]) continue;
        const int s = solid(game, e);
        if (s == qc::kSolidNot || s == qc::kSolidTrigger) {
            Vec3f mins = vm.field_vector(e, f.mins);
            mins[0] = mins[1] = 0;
            vm.set_field_vector(e, f.mins, mins);
            vm.set_field_vector(e, f.maxs, mins);
            continue;
        }
        undo_push(game, pusher, e, pusher_from, move_time, moved);
        return;
    }
}

void physics_pusher(GameState& game, uint32_t pusher, std::vector<MovedEdict>& moved) {
    vm::Vm& vm = game.vm;
    const FieldOffsets& f = game.f();
    const float old_ltime = vm.field_float(pusher, f.ltime);
    const float think_time = vm.field_float(pusher, f.nextthink);
    // Move up to the think time when it comes within this frame: the think then starts the
    // next leg of the pusher's path exactly there.
    float move_time = game.frame_time;
    if (double(think_time) < double(old_ltime) + double(game.frame_time)) {
        move_time = think_time - old_ltime;
        if (move_time < 0) move_time = 0;
    }
    if (move_time != 0) push_move(game, pusher, move_time, moved);
    if (think_time > old_ltime && think_time <= vm.field_float(pusher, f.ltime)) {
        vm.set_field_float(pusher, f.nextthink, 0);
        vm.set_global_float(game.g().time, float(game.time));
        call_qc(game, vm.field_int(pusher, f.think), pusher, 0);
    }
}

}  // namespace nq::server::physics

#include "server/physics_walk.h"

#include <cmath>

#include "server/physics_motion.h"
#include "server/qmath.h"
#include "server/server_host.h"
#include "server/world.h"

namespace nq::server::physics {

namespace {

using vm::Vec3f;

bool is_stuck(GameState& game, uint32_t edict) {
    return game.world.test_entity_position(edict).has_value();
}

void unstuck(GameState& game, uint32_t edict, ServerHost* host) {
    if (host) host->debug_print("Unstuck.\n");
    game.world.link(edict, true);
}

// SV_WallFriction: running into a wall you face slows you along it.
void wall_friction(GameState& game, uint32_t edict, const MoveTrace& wall) {
    vm::Vm& vm = game.vm;
    const FieldOffsets& f = game.f();
    const Vec3f forward = angle_vectors(vm.field_vector(edict, f.v_angle)).forward;
    const float facing = vdot(wall.plane_normal, forward) + 0.5f;
    if (facing >= 0) return;
    Vec3f velocity = vm.field_vector(edict, f.velocity);
    const float into = vdot(wall.plane_normal, velocity);
    const Vec3f side = vsub(velocity, vscale(wall.plane_normal, into));
    velocity[0] = side[0] * (1 + facing);
    velocity[1] = side[1] * (1 + facing);
    vm.set_field_vector(edict, f.velocity, velocity);
}

void set_horizontal_velocity(GameState& game, uint32_t edict, const Vec3f& from) {
    game.vm.set_field_vector(edict, game.f().velocity, {from[0], from[1], 0});
}

// SV_TryUnstick: the step-up made no progress, perhaps snagged on the hulls' limited precision;
// nudge 2 units each way in turn and retry a short move.
int try_unstick(GameState& game, uint32_t edict, const Vec3f& old_velocity) {
    static constexpr float kNudges[8][2] = {{2, 0}, {0, 2},  {-2, 0}, {0, -2},
                                            {2, 2}, {-2, 2}, {2, -2}, {-2, -2}};
    vm::Vm& vm = game.vm;
    const FieldOffsets& f = game.f();
    const Vec3f start = vm.field_vector(edict, f.origin);
    for (const auto& nudge : kNudges) {
        push_entity(game, edict, {nudge[0], nudge[1], 0});
        set_horizontal_velocity(game, edict, old_velocity);
        MoveTrace step_trace;
        const int clip = fly_move(game, edict, 0.1f, &step_trace);
        const Vec3f now = vm.field_vector(edict, f.origin);
        if (std::fabs(start[1] - now[1]) > 4 || std::fabs(start[0] - now[0]) > 4) return clip;
        vm.set_field_vector(edict, f.origin, start);
    }
    vm.set_field_vector(edict, f.velocity, {0, 0, 0});
    return kBlockedTrapped;
}

// Whether the plain slide move should be retried as a step up.
bool may_step(GameState& game, uint32_t edict, int clip, bool was_on_ground) {
    if (!(clip & kBlockedStep)) return false;
    // No stair climbing in mid-jump (swimming players may).
    if (!was_on_ground && game.vm.field_float(edict, game.f().waterlevel) == 0) return false;
    if (movetype(game, edict) != qc::kMoveWalk) return false;  // gibbed by a trigger
    if (game.settings.no_step) return false;
    return !(flags(game, edict) & qc::kFlWaterJump);
}

}  // namespace

void check_stuck(GameState& game, uint32_t edict, ServerHost* host) {
    vm::Vm& vm = game.vm;
    const FieldOffsets& f = game.f();
    const Vec3f origin = vm.field_vector(edict, f.origin);
    if (!is_stuck(game, edict)) {
        vm.set_field_vector(edict, f.oldorigin, origin);
        return;
    }
    vm.set_field_vector(edict, f.origin, vm.field_vector(edict, f.oldorigin));
    if (!is_stuck(game, edict)) return unstuck(game, edict, host);
    for (int z = 0; z < 18; ++z) {
        for (int x = -1; x <= 1; ++x) {
            for (int y = -1; y <= 1; ++y) {
                vm.set_field_vector(
                    edict, f.origin,
                    {origin[0] + float(x), origin[1] + float(y), origin[2] + float(z)});
                if (!is_stuck(game, edict)) return unstuck(game, edict, host);
            }
        }
    }
    vm.set_field_vector(edict, f.origin, origin);
    if (host) host->debug_print("player is stuck.\n");
}

void player_walk_move(GameState& game, uint32_t edict) {
    vm::Vm& vm = game.vm;
    const FieldOffsets& f = game.f();
    const int old_flags = flags(game, edict);
    const bool was_on_ground = old_flags & qc::kFlOnGround;
    set_flags(game, edict, old_flags & ~qc::kFlOnGround);
    const Vec3f old_origin = vm.field_vector(edict, f.origin);
    const Vec3f old_velocity = vm.field_vector(edict, f.velocity);

    MoveTrace step_trace;
    int clip = fly_move(game, edict, game.frame_time, &step_trace);
    if (!may_step(game, edict, clip, was_on_ground)) return;

    const Vec3f slide_origin = vm.field_vector(edict, f.origin);
    const Vec3f slide_velocity = vm.field_vector(edict, f.velocity);
    // Again from the start: up a step, forward, and back down.
    vm.set_field_vector(edict, f.origin, old_origin);
    push_entity(game, edict, {0, 0, game.settings.step_size});
    set_horizontal_velocity(game, edict, old_velocity);
    clip = fly_move(game, edict, game.frame_time, &step_trace);
    if (clip) {
        const Vec3f now = vm.field_vector(edict, f.origin);
        if (std::fabs(old_origin[1] - now[1]) < 0.03125f &&
            std::fabs(old_origin[0] - now[0]) < 0.03125f) {
            clip = try_unstick(game, edict, old_velocity);
        }
    }
    if (clip & kBlockedStep) wall_friction(game, edict, step_trace);

    const float down = -game.settings.step_size + old_velocity[2] * game.frame_time;
    const MoveTrace down_trace = push_entity(game, edict, {0, 0, down});
    if (down_trace.plane_normal[2] > 0.7f) {
        // Quake tests the player's own solid here, which is never BSP: stepping up does not set
        // FL_ONGROUND, the next frame's fall onto the step does.
        if (solid(game, edict) == qc::kSolidBsp) {
            set_flags(game, edict, flags(game, edict) | qc::kFlOnGround);
            set_edict_field(game, edict, f.groundentity, down_trace.entity.value_or(0));
        }
        return;
    }
    // Not good ground (a wall next to a steep slope): keep the plain slide instead, so players
    // cannot hop up slopes too steep to climb.
    vm.set_field_vector(edict, f.origin, slide_origin);
    vm.set_field_vector(edict, f.velocity, slide_velocity);
}

}  // namespace nq::server::physics

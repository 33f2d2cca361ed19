#include "server/monster_move.h"

#include <cmath>
#include <utility>

#include "formats/bsp.h"
#include "server/physics_motion.h"
#include "server/qmath.h"
#include "server/world.h"

namespace nq::server {

namespace {

using namespace physics;
using vm::Vec3f;

constexpr float kNoDir = -1;  // DI_NODIR

Vec3f yaw_move(float yaw_degrees, float dist) {
    const double yaw = double(yaw_degrees) * M_PI * 2 / 360;
    return {float(std::cos(yaw) * dist), float(std::sin(yaw) * dist), 0};
}

void relink_if(GameState& game, uint32_t edict, bool relink) {
    if (relink) game.world.link(edict, true);
}

// Flyers and swimmers: first a move that also closes in on the enemy's height, then a level one.
bool fly_step(GameState& game, uint32_t edict, const Vec3f& move, bool relink) {
    vm::Vm& vm = game.vm;
    const FieldOffsets& f = game.f();
    const uint32_t enemy = edict_field(game, edict, f.enemy);
    for (int attempt = 0; attempt < 2; ++attempt) {
        const Vec3f origin = vm.field_vector(edict, f.origin);
        Vec3f target = vadd(origin, move);
        if (attempt == 0 && enemy != 0) {
            const float dz = origin[2] - vm.field_vector(enemy, f.origin)[2];
            if (dz > 40) target[2] -= 8;
            if (dz < 30) target[2] += 8;
        }
        const MoveTrace trace =
            game.world.move(origin, vm.field_vector(edict, f.mins), vm.field_vector(edict, f.maxs),
                            target, MoveKind::normal, edict);
        if (trace.fraction == 1) {
            // Swimmers stay in the water.
            if ((flags(game, edict) & qc::kFlSwim) &&
                game.world.point_contents(trace.end_pos) == bsp_contents::empty) {
                return false;
            }
            vm.set_field_vector(edict, f.origin, trace.end_pos);
            relink_if(game, edict, relink);
            return true;
        }
        if (enemy == 0) break;
    }
    return false;
}

// Walkers: drop onto the new spot from a step above it, down to a step below it.
bool ground_step(GameState& game, uint32_t edict, const Vec3f& move, bool relink) {
    vm::Vm& vm = game.vm;
    const FieldOffsets& f = game.f();
    const float step = game.settings.step_size;
    const Vec3f old_origin = vm.field_vector(edict, f.origin);
    const Vec3f mins = vm.field_vector(edict, f.mins);
    const Vec3f maxs = vm.field_vector(edict, f.maxs);
    Vec3f top = vadd(old_origin, move);
    top[2] += step;
    const Vec3f bottom = {top[0], top[1], top[2] - 2 * step};
    MoveTrace trace = game.world.move(top, mins, maxs, bottom, MoveKind::normal, edict);
    if (trace.all_solid) return false;
    if (trace.start_solid) {  // no room a step up: try from level
        top[2] -= step;
        trace = game.world.move(top, mins, maxs, bottom, MoveKind::normal, edict);
        if (trace.all_solid || trace.start_solid) return false;
    }
    const int fl = flags(game, edict);
    if (trace.fraction == 1) {
        // Nothing below: only a monster whose ground was pulled away may go (and fall).
        if (!(fl & qc::kFlPartialGround)) return false;
        vm.set_field_vector(edict, f.origin, vadd(old_origin, move));
        relink_if(game, edict, relink);
        set_flags(game, edict, flags(game, edict) & ~qc::kFlOnGround);
        return true;
    }
    vm.set_field_vector(edict, f.origin, trace.end_pos);
    if (!check_bottom(game, edict)) {
        if (fl & qc::kFlPartialGround) {  // still correcting a half-lost footing
            relink_if(game, edict, relink);
            return true;
        }
        vm.set_field_vector(edict, f.origin, old_origin);
        return false;
    }
    if (fl & qc::kFlPartialGround) set_flags(game, edict, fl & ~qc::kFlPartialGround);
    set_edict_field(game, edict, f.groundentity, trace.entity.value_or(0));
    relink_if(game, edict, relink);
    return true;
}

// SV_movestep.
bool move_step(GameState& game, uint32_t edict, const Vec3f& move, bool relink) {
    if (flags(game, edict) & (qc::kFlSwim | qc::kFlFly)) return fly_step(game, edict, move, relink);
    return ground_step(game, edict, move, relink);
}

// SV_StepDirection: turn toward `yaw` and step that way; a monster still facing more than 45
// degrees away turns without moving.
bool step_direction(GameState& game, uint32_t edict, float yaw, float dist) {
    vm::Vm& vm = game.vm;
    const FieldOffsets& f = game.f();
    vm.set_field_float(edict, f.ideal_yaw, yaw);
    change_yaw(game, edict);
    const Vec3f old_origin = vm.field_vector(edict, f.origin);
    const bool moved = move_step(game, edict, yaw_move(yaw, dist), false);
    if (moved) {
        const float delta =
            vm.field_vector(edict, f.angles)[1] - vm.field_float(edict, f.ideal_yaw);
        if (delta > 45 && delta < 315) vm.set_field_vector(edict, f.origin, old_origin);
    }
    game.world.link(edict, true);
    return moved;
}

bool try_direction(GameState& game, uint32_t edict, float dir, float turnaround, float dist) {
    return dir != kNoDir && dir != turnaround && step_direction(game, edict, dir, dist);
}

// The axis directions (0/180 and 90/270) toward the enemy, kNoDir when within 10 units.
void directions_to(const Vec3f& delta, float& x_dir, float& y_dir) {
    x_dir = delta[0] > 10 ? 0 : delta[0] < -10 ? 180 : kNoDir;
    y_dir = delta[1] < -10 ? 270 : delta[1] > 10 ? 90 : kNoDir;
}

// The last resort: any of the eight directions, searched clockwise or counter-clockwise.
bool try_all_directions(GameState& game, uint32_t edict, float turnaround, float dist,
                        GameRandom& random) {
    const bool up = random.next() < 0.5f;
    for (int i = 0; i < 8; ++i) {
        const float dir = float(up ? i * 45 : 315 - i * 45);
        if (dir != turnaround && step_direction(game, edict, dir, dist)) return true;
    }
    return false;
}

// SV_NewChaseDir: the direct diagonal toward the goal, else its axis directions (in a random
// or the longer-first order), else the old direction, else anything but turning around, else
// turning around. Never reverses while another way is open.
void new_chase_dir(GameState& game, uint32_t edict, uint32_t goal, float dist, GameRandom& random) {
    vm::Vm& vm = game.vm;
    const FieldOffsets& f = game.f();
    const float old_dir =
        qmath::angle_mod(float(int(vm.field_float(edict, f.ideal_yaw) / 45) * 45));
    const float turnaround = qmath::angle_mod(old_dir - 180);
    const Vec3f delta = vsub(vm.field_vector(goal, f.origin), vm.field_vector(edict, f.origin));
    float d1 = kNoDir, d2 = kNoDir;
    directions_to(delta, d1, d2);
    if (d1 != kNoDir && d2 != kNoDir) {
        // 215 rather than 225 is Quake's own value; chase paths depend on it.
        const float diagonal = d1 == 0 ? (d2 == 90 ? 45 : 315) : (d2 == 90 ? 135 : 215);
        if (diagonal != turnaround && step_direction(game, edict, diagonal, dist)) return;
    }
    if (random.next() < 0.5f || std::fabs(float(int(delta[1]))) > std::fabs(float(int(delta[0])))) {
        std::swap(d1, d2);
    }
    if (try_direction(game, edict, d1, turnaround, dist)) return;
    if (try_direction(game, edict, d2, turnaround, dist)) return;
    if (step_direction(game, edict, old_dir, dist)) return;
    if (try_all_directions(game, edict, turnaround, dist, random)) return;
    if (step_direction(game, edict, turnaround, dist)) return;
    vm.set_field_float(edict, f.ideal_yaw, old_dir);  // cannot move
    // A bridge pulled out from under it: let it fall rather than stand on nothing.
    if (!check_bottom(game, edict)) {
        set_flags(game, edict, flags(game, edict) | qc::kFlPartialGround);
    }
}

// SV_CloseEnough: whether the goal's box comes within `dist` of the edict's on every axis.
bool close_enough(const GameState& game, uint32_t edict, uint32_t goal, float dist) {
    const FieldOffsets& f = game.f();
    const Vec3f goal_min = game.vm.field_vector(goal, f.absmin);
    const Vec3f goal_max = game.vm.field_vector(goal, f.absmax);
    const Vec3f min = game.vm.field_vector(edict, f.absmin);
    const Vec3f max = game.vm.field_vector(edict, f.absmax);
    for (int i = 0; i < 3; ++i) {
        if (goal_min[i] > max[i] + dist || goal_max[i] < min[i] - dist) return false;
    }
    return true;
}

bool can_move(const GameState& game, uint32_t edict) {
    return flags(game, edict) & (qc::kFlOnGround | qc::kFlFly | qc::kFlSwim);
}

// Corner points of the box's bottom, one z.
Vec3f corner(const Vec3f& mins, const Vec3f& maxs, int x, int y, float z) {
    return {x ? maxs[0] : mins[0], y ? maxs[1] : mins[1], z};
}

}  // namespace

bool check_bottom(GameState& game, uint32_t edict) {
    vm::Vm& vm = game.vm;
    const FieldOffsets& f = game.f();
    const Vec3f origin = vm.field_vector(edict, f.origin);
    const Vec3f mins = vadd(origin, vm.field_vector(edict, f.mins));
    const Vec3f maxs = vadd(origin, vm.field_vector(edict, f.maxs));
    // Solid world just under all four corners: certainly standing.
    bool all_solid = true;
    for (int i = 0; i < 4 && all_solid; ++i) {
        all_solid = game.world.point_contents(corner(mins, maxs, i & 1, i >> 1, mins[2] - 1)) ==
                    bsp_contents::solid;
    }
    if (all_solid) return true;

    // Else trace down from the middle and each corner: none may be more than a step below
    // the middle.
    const float step = game.settings.step_size;
    const Vec3f start = {(mins[0] + maxs[0]) * 0.5f, (mins[1] + maxs[1]) * 0.5f, mins[2]};
    const Vec3f stop = {start[0], start[1], start[2] - 2 * step};
    const Vec3f zero = {0, 0, 0};
    const MoveTrace middle = game.world.move(start, zero, zero, stop, MoveKind::no_monsters, edict);
    if (middle.fraction == 1) return false;
    const float mid = middle.end_pos[2];
    for (int i = 0; i < 4; ++i) {
        const MoveTrace trace = game.world.move(corner(mins, maxs, i & 1, i >> 1, start[2]), zero,
                                                zero, corner(mins, maxs, i & 1, i >> 1, stop[2]),
                                                MoveKind::no_monsters, edict);
        if (trace.fraction == 1 || mid - trace.end_pos[2] > step) return false;
    }
    return true;
}

void change_yaw(GameState& game, uint32_t edict) {
    vm::Vm& vm = game.vm;
    const FieldOffsets& f = game.f();
    Vec3f angles = vm.field_vector(edict, f.angles);
    const float current = qmath::angle_mod(angles[1]);
    const float ideal = vm.field_float(edict, f.ideal_yaw);
    const float speed = vm.field_float(edict, f.yaw_speed);
    if (current == ideal) return;
    float move = ideal - current;
    // The short way round.
    if (ideal > current) {
        if (move >= 180) move -= 360;
    } else if (move <= -180) {
        move += 360;
    }
    if (move > 0) {
        if (move > speed) move = speed;
    } else if (move < -speed) {
        move = -speed;
    }
    angles[1] = qmath::angle_mod(current + move);
    vm.set_field_vector(edict, f.angles, angles);
}

bool walk_move(GameState& game, uint32_t edict, float yaw, float dist, bool relink) {
    if (!can_move(game, edict)) return false;
    // Touch functions run while relinking may change self; the calling QuakeC expects it back.
    const uint32_t self = game.vm.global_word(game.g().self);
    const bool moved = move_step(game, edict, yaw_move(yaw, dist), relink);
    game.vm.set_global_word(game.g().self, self);
    return moved;
}

void move_to_goal(GameState& game, uint32_t edict, float dist, GameRandom& random) {
    const FieldOffsets& f = game.f();
    if (!can_move(game, edict)) return;
    const uint32_t goal = edict_field(game, edict, f.goalentity);
    // The next step would reach the enemy: attack rather than move.
    if (edict_field(game, edict, f.enemy) != 0 && close_enough(game, edict, goal, dist)) return;
    const bool change = random.next() < 0.25f;
    if (change || !step_direction(game, edict, game.vm.field_float(edict, f.ideal_yaw), dist)) {
        new_chase_dir(game, edict, goal, dist, random);
    }
}

bool drop_to_floor(GameState& game, uint32_t edict) {
    vm::Vm& vm = game.vm;
    const FieldOffsets& f = game.f();
    const Vec3f origin = vm.field_vector(edict, f.origin);
    const Vec3f end = {origin[0], origin[1], origin[2] - 256};
    const MoveTrace trace =
        game.world.move(origin, vm.field_vector(edict, f.mins), vm.field_vector(edict, f.maxs), end,
                        MoveKind::normal, edict);
    if (trace.fraction == 1 || trace.all_solid) return false;
    vm.set_field_vector(edict, f.origin, trace.end_pos);
    game.world.link(edict, false);
    set_flags(game, edict, flags(game, edict) | qc::kFlOnGround);
    set_edict_field(game, edict, f.groundentity, trace.entity.value_or(0));
    return true;
}

}  // namespace nq::server

#include "server/player_move.h"

#include <cmath>

#include "server/physics_motion.h"
#include "server/qmath.h"
#include "server/world.h"

namespace nq::server {

namespace {

using namespace physics;
using vm::Vec3f;

constexpr float kRollAngle = 2;    // cl_rollangle
constexpr float kRollSpeed = 200;  // cl_rollspeed
constexpr int kPitch = 0, kYaw = 1, kRoll = 2;

// VectorNormalize: scales `v` to unit length (a zero vector stays zero), returns the length.
float normalize(Vec3f& v) {
    const float len = vlength(v);
    if (len != 0) v = vscale(v, 1 / len);
    return len;
}

// One player's command being turned into velocity (SV_ClientThink's shared state).
struct PlayerMove {
    GameState& game;
    uint32_t edict;
    const UserCmd& cmd;
    Vec3f velocity;
};

// Punches (recoil, damage kicks) fade at 10 degrees a second.
void drop_punch_angle(GameState& game, uint32_t edict) {
    const uint32_t field = game.f().punchangle;
    Vec3f punch = game.vm.field_vector(edict, field);
    float len = normalize(punch) - 10 * game.frame_time;
    if (len < 0) len = 0;
    game.vm.set_field_vector(edict, field, vscale(punch, len));
}

// SV_UserFriction: ground friction, doubled (sv_edgefriction) when the ground 16 units ahead
// falls away by more than 34, so players slow down before ledges.
void user_friction(PlayerMove& m) {
    Vec3f& vel = m.velocity;
    const float speed = std::sqrt(vel[0] * vel[0] + vel[1] * vel[1]);
    if (speed == 0) return;
    vm::Vm& vm = m.game.vm;
    const Vec3f origin = vm.field_vector(m.edict, m.game.f().origin);
    Vec3f start = {origin[0] + vel[0] / speed * 16, origin[1] + vel[1] / speed * 16,
                   origin[2] + vm.field_vector(m.edict, m.game.f().mins)[2]};
    const Vec3f stop = {start[0], start[1], start[2] - 34};
    const MoveTrace trace =
        m.game.world.move(start, {0, 0, 0}, {0, 0, 0}, stop, MoveKind::no_monsters, m.edict);
    const PhysicsSettings& s = m.game.settings;
    const float friction = trace.fraction == 1 ? s.friction * s.edge_friction : s.friction;
    const float control = speed < s.stop_speed ? s.stop_speed : speed;
    float new_speed = speed - m.game.frame_time * control * friction;
    if (new_speed < 0) new_speed = 0;
    vel = vscale(vel, new_speed / speed);
}

// SV_Accelerate: towards wishspeed along wishdir, at most sv_accelerate * wishspeed per second.
void accelerate(PlayerMove& m, float wish_speed, const Vec3f& wish_dir) {
    const float add_speed = wish_speed - vdot(m.velocity, wish_dir);
    if (add_speed <= 0) return;
    float accel_speed = m.game.settings.accelerate * m.game.frame_time * wish_speed;
    if (accel_speed > add_speed) accel_speed = add_speed;
    m.velocity = vmad(m.velocity, accel_speed, wish_dir);
}

// SV_AirAccelerate: in the air only the first 30 units/s along the wish direction can be
// gained, at the full ground rate (this is what makes air strafing work).
void air_accelerate(PlayerMove& m, float wish_speed, Vec3f wish_velocity) {
    float capped = normalize(wish_velocity);
    if (capped > 30) capped = 30;
    const float add_speed = capped - vdot(m.velocity, wish_velocity);
    if (add_speed <= 0) return;
    float accel_speed = m.game.settings.accelerate * wish_speed * m.game.frame_time;
    if (accel_speed > add_speed) accel_speed = add_speed;
    m.velocity = vmad(m.velocity, accel_speed, wish_velocity);
}

// SV_WaterMove: swim where the view points at 70% speed, sink slowly when idle.
void water_move(PlayerMove& m) {
    const PhysicsSettings& s = m.game.settings;
    const float dt = m.game.frame_time;
    const Basis b = angle_vectors(m.game.vm.field_vector(m.edict, m.game.f().v_angle));
    Vec3f wish = vadd(vscale(b.forward, m.cmd.forward_move), vscale(b.right, m.cmd.side_move));
    if (m.cmd.forward_move == 0 && m.cmd.side_move == 0 && m.cmd.up_move == 0) {
        wish[2] -= 60;
    } else {
        wish[2] += m.cmd.up_move;
    }
    float wish_speed = vlength(wish);
    if (wish_speed > s.max_speed) {
        wish = vscale(wish, s.max_speed / wish_speed);
        wish_speed = s.max_speed;
    }
    wish_speed *= 0.7f;

    const float speed = vlength(m.velocity);
    float new_speed = 0;
    if (speed != 0) {
        new_speed = speed - dt * speed * s.water_friction;
        if (new_speed < 0) new_speed = 0;
        m.velocity = vscale(m.velocity, new_speed / speed);
    }
    if (wish_speed == 0) return;
    const float add_speed = wish_speed - new_speed;
    if (add_speed <= 0) return;
    normalize(wish);
    float accel_speed = s.water_accelerate * wish_speed * dt;
    if (accel_speed > add_speed) accel_speed = add_speed;
    m.velocity = vmad(m.velocity, accel_speed, wish);
}

// SV_WaterJump: QuakeC launched the player out of water; keep its horizontal push (movedir)
// until teleport_time or until out of the water.
void water_jump(PlayerMove& m) {
    vm::Vm& vm = m.game.vm;
    const FieldOffsets& f = m.game.f();
    if (m.game.time > double(vm.field_float(m.edict, f.teleport_time)) ||
        vm.field_float(m.edict, f.waterlevel) == 0) {
        set_flags(m.game, m.edict, flags(m.game, m.edict) & ~qc::kFlWaterJump);
        vm.set_field_float(m.edict, f.teleport_time, 0);
    }
    const Vec3f push = vm.field_vector(m.edict, f.movedir);
    m.velocity[0] = push[0];
    m.velocity[1] = push[1];
}

// SV_AirMove: walking, falling, flying and noclip, steered by the body's angles.
void air_move(PlayerMove& m, bool on_ground) {
    vm::Vm& vm = m.game.vm;
    const FieldOffsets& f = m.game.f();
    const PhysicsSettings& s = m.game.settings;
    const Basis b = angle_vectors(vm.field_vector(m.edict, f.angles));
    float forward_move = m.cmd.forward_move;
    // Just teleported: no backing into the teleporter.
    if (m.game.time < double(vm.field_float(m.edict, f.teleport_time)) && forward_move < 0) {
        forward_move = 0;
    }
    Vec3f wish = vadd(vscale(b.forward, forward_move), vscale(b.right, m.cmd.side_move));
    const int type = movetype(m.game, m.edict);
    wish[2] = type != qc::kMoveWalk ? m.cmd.up_move : 0;
    Vec3f wish_dir = wish;
    float wish_speed = normalize(wish_dir);
    if (wish_speed > s.max_speed) {
        wish = vscale(wish, s.max_speed / wish_speed);
        wish_speed = s.max_speed;
    }
    if (type == qc::kMoveNoclip) {
        m.velocity = wish;
    } else if (on_ground) {
        user_friction(m);
        accelerate(m, wish_speed, wish_dir);
    } else {
        air_accelerate(m, wish_speed, wish);
    }
}

// The body shows a third of the view's pitch and rolls with sideways speed.
void set_body_angles(GameState& game, uint32_t edict) {
    vm::Vm& vm = game.vm;
    const FieldOffsets& f = game.f();
    const Vec3f view =
        vadd(vm.field_vector(edict, f.v_angle), vm.field_vector(edict, f.punchangle));
    Vec3f angles = vm.field_vector(edict, f.angles);
    angles[kRoll] = calc_roll(angles, vm.field_vector(edict, f.velocity)) * 4;
    if (vm.field_float(edict, f.fixangle) == 0) {
        angles[kPitch] = -view[kPitch] / 3;
        angles[kYaw] = view[kYaw];
    }
    vm.set_field_vector(edict, f.angles, angles);
}

}  // namespace

float calc_roll(const Vec3f& angles, const Vec3f& velocity) {
    float side = vdot(velocity, angle_vectors(angles).right);
    const float sign = side < 0 ? -1.0f : 1.0f;
    side = std::fabs(side);
    side = side < kRollSpeed ? side * kRollAngle / kRollSpeed : kRollAngle;
    return side * sign;
}

void apply_user_cmd(GameState& game, uint32_t edict, const UserCmd& cmd) {
    vm::Vm& vm = game.vm;
    const FieldOffsets& f = game.f();
    vm.set_field_vector(edict, f.v_angle, cmd.view_angles);
    vm.set_field_float(edict, f.button0, float(cmd.buttons & 1));
    vm.set_field_float(edict, f.button2, float((cmd.buttons & 2) >> 1));
    if (cmd.impulse) vm.set_field_float(edict, f.impulse, float(cmd.impulse));
}

void client_think(GameState& game, uint32_t edict, const UserCmd& cmd) {
    vm::Vm& vm = game.vm;
    const FieldOffsets& f = game.f();
    if (movetype(game, edict) == qc::kMoveNone) return;
    const bool on_ground = flags(game, edict) & qc::kFlOnGround;
    drop_punch_angle(game, edict);
    if (vm.field_float(edict, f.health) <= 0) return;  // the dead only fall
    set_body_angles(game, edict);

    PlayerMove move{game, edict, cmd, vm.field_vector(edict, f.velocity)};
    if (flags(game, edict) & qc::kFlWaterJump) {
        water_jump(move);
    } else if (vm.field_float(edict, f.waterlevel) >= 2 &&
               movetype(game, edict) != qc::kMoveNoclip) {
        water_move(move);
    } else {
        air_move(move, on_ground);
    }
    vm.set_field_vector(edict, f.velocity, move.velocity);
}

}  // namespace nq::server

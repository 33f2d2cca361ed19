#include "server/physics.h"

#include <string>

#include "server/physics_motion.h"
#include "server/physics_walk.h"
#include "server/qmath.h"
#include "server/server_host.h"
#include "server/world.h"

namespace nq::server {

namespace {

using namespace physics;
using vm::Vec3f;

void physics_noclip(GameState& game, uint32_t edict) {
    if (!run_think(game, edict)) return;
    vm::Vm& vm = game.vm;
    const FieldOffsets& f = game.f();
    vm.set_field_vector(edict, f.angles,
                        vmad(vm.field_vector(edict, f.angles), game.frame_time,
                             vm.field_vector(edict, f.avelocity)));
    vm.set_field_vector(edict, f.origin,
                        vmad(vm.field_vector(edict, f.origin), game.frame_time,
                             vm.field_vector(edict, f.velocity)));
    game.world.link(edict, false);
}

// SV_Physics_Toss: grenades, gibs, rockets, items thrown out of backpacks.
void physics_toss(GameState& game, uint32_t edict, ServerHost* host) {
    if (!run_think(game, edict)) return;
    if (flags(game, edict) & qc::kFlOnGround) return;  // at rest until something lifts it
    check_velocity(game, edict, host);
    vm::Vm& vm = game.vm;
    const FieldOffsets& f = game.f();
    const int type = movetype(game, edict);
    if (type != qc::kMoveFly && type != qc::kMoveFlyMissile) add_gravity(game, edict);
    vm.set_field_vector(edict, f.angles,
                        vmad(vm.field_vector(edict, f.angles), game.frame_time,
                             vm.field_vector(edict, f.avelocity)));
    const Vec3f move = vscale(vm.field_vector(edict, f.velocity), game.frame_time);
    const MoveTrace trace = push_entity(game, edict, move);
    // Quake looks for water only after hitting something, so a free flight never splashes.
    if (trace.fraction == 1 || game.edicts.is_free(edict)) return;

    const float overbounce = type == qc::kMoveBounce ? 1.5f : 1.0f;
    Vec3f velocity = vm.field_vector(edict, f.velocity);
    clip_velocity(velocity, trace.plane_normal, velocity, overbounce);
    vm.set_field_vector(edict, f.velocity, velocity);
    // Resting on a floor: everything but a bounce stops at once, a bounce once it is slow.
    if (trace.plane_normal[2] > 0.7f && (velocity[2] < 60 || type != qc::kMoveBounce)) {
        set_flags(game, edict, flags(game, edict) | qc::kFlOnGround);
        set_edict_field(game, edict, f.groundentity, trace.entity.value_or(0));
        vm.set_field_vector(edict, f.velocity, {0, 0, 0});
        vm.set_field_vector(edict, f.avelocity, {0, 0, 0});
    }
    check_water_transition(game, edict);
}

// SV_Physics_Step: monsters. They fall when nothing holds them up (flyers and swimmers never
// do), with a thud when they land fast; walking itself is their QuakeC's walkmove/movetogoal.
void physics_step(GameState& game, uint32_t edict, ServerHost* host) {
    if (!(flags(game, edict) & (qc::kFlOnGround | qc::kFlFly | qc::kFlSwim))) {
        const bool hit_sound =
            game.vm.field_vector(edict, game.f().velocity)[2] < game.settings.gravity * -0.1f;
        add_gravity(game, edict);
        check_velocity(game, edict, host);
        fly_move(game, edict, game.frame_time, nullptr);
        game.world.link(edict, true);
        if ((flags(game, edict) & qc::kFlOnGround) && hit_sound) {
            start_sound(game, edict, "demon/dland2.wav");
        }
    }
    run_think(game, edict);
    if (!game.edicts.is_free(edict)) check_water_transition(game, edict);
}

// The movetype-dependent part of a player's frame; false when the player's think removed it.
bool move_client(GameState& game, uint32_t edict, int type, ServerHost* host) {
    vm::Vm& vm = game.vm;
    switch (type) {
        case qc::kMoveNone:
            return run_think(game, edict);
        case qc::kMoveWalk:
            if (!run_think(game, edict)) return false;
            if (!check_water(game, edict) && !(flags(game, edict) & qc::kFlWaterJump)) {
                add_gravity(game, edict);
            }
            check_stuck(game, edict, host);
            player_walk_move(game, edict);
            return true;
        case qc::kMoveToss:
        case qc::kMoveBounce:
            physics_toss(game, edict, host);
            return true;
        case qc::kMoveFly:
            if (!run_think(game, edict)) return false;
            fly_move(game, edict, game.frame_time, nullptr);
            return true;
        case qc::kMoveNoclip:
            if (!run_think(game, edict)) return false;
            vm.set_field_vector(edict, game.f().origin,
                                vmad(vm.field_vector(edict, game.f().origin), game.frame_time,
                                     vm.field_vector(edict, game.f().velocity)));
            return true;
        default:
            return run_think(game, edict);
    }
}

// Quake stops the whole program on an unknown movetype; we say so once and let the entity stand.
int checked_movetype(GameState& game, uint32_t edict, ServerHost* host, bool client) {
    const int type = movetype(game, edict);
    switch (type) {
        case qc::kMoveNone:
        case qc::kMoveWalk:
        case qc::kMoveStep:
        case qc::kMoveFly:
        case qc::kMoveToss:
        case qc::kMovePush:
        case qc::kMoveNoclip:
        case qc::kMoveFlyMissile:
        case qc::kMoveBounce:
            if (!client ||
                (type != qc::kMoveStep && type != qc::kMovePush && type != qc::kMoveFlyMissile)) {
                return type;
            }
            break;
        default:
            break;
    }
    if (host) {
        host->print("bad movetype " + std::to_string(type) + " on edict " + std::to_string(edict) +
                    ": now MOVETYPE_NONE\n");
    }
    game.vm.set_field_float(edict, game.f().movetype, float(qc::kMoveNone));
    return qc::kMoveNone;
}

// SV_Physics_Client.
void physics_client(GameState& game, uint32_t edict, ServerHost* host) {
    vm::Vm& vm = game.vm;
    const GlobalOffsets& g = game.g();
    vm.set_global_float(g.time, float(game.time));
    call_qc(game, int32_t(vm.global_word(g.PlayerPreThink)), edict, 0);
    check_velocity(game, edict, host);
    if (!move_client(game, edict, checked_movetype(game, edict, host, true), host)) return;
    game.world.link(edict, true);
    vm.set_global_float(g.time, float(game.time));
    call_qc(game, int32_t(vm.global_word(g.PlayerPostThink)), edict, 0);
}

void physics_entity(GameState& game, uint32_t edict, PhysicsContext& context) {
    switch (checked_movetype(game, edict, context.host, false)) {
        case qc::kMovePush:
            physics_pusher(game, edict, context.moved);
            break;
        case qc::kMoveNoclip:
            physics_noclip(game, edict);
            break;
        case qc::kMoveStep:
            physics_step(game, edict, context.host);
            break;
        case qc::kMoveToss:
        case qc::kMoveBounce:
        case qc::kMoveFly:
        case qc::kMoveFlyMissile:
            physics_toss(game, edict, context.host);
            break;
        default:  // MOVETYPE_NONE and players' MOVETYPE_WALK outside a client slot
            run_think(game, edict);
            break;
    }
}

bool client_spawned(std::span<const uint8_t> clients_spawned, uint32_t edict) {
    return edict - 1 < clients_spawned.size() && clients_spawned[edict - 1] != 0;
}

}  // namespace

bool run_physics(GameState& game, std::span<const uint8_t> clients_spawned,
                 PhysicsContext& context) {
    vm::Vm& vm = game.vm;
    const GlobalOffsets& g = game.g();
    vm.set_global_float(g.frametime, game.frame_time);
    vm.set_global_float(g.time, float(game.time));
    if (!call_qc(game, int32_t(vm.global_word(g.StartFrame)), 0, 0)) return false;

    const uint32_t max_clients = game.edicts.max_clients();
    // num_edicts may grow while we run: entities spawned this frame move this frame too.
    for (uint32_t e = 0; e < vm.num_edicts(); ++e) {
        if (game.edicts.is_free(e)) continue;
        if (vm.global_float(g.force_retouch) != 0) game.world.link(e, true);
        if (e >= 1 && e <= max_clients) {
            if (client_spawned(clients_spawned, e)) physics_client(game, e, context.host);
        } else {
            physics_entity(game, e, context);
        }
        if (vm.error()) return false;
    }
    const float retouch = vm.global_float(g.force_retouch);
    if (retouch != 0) vm.set_global_float(g.force_retouch, retouch - 1);
    return true;
}

}  // namespace nq::server

// Where the engine finds Quake's system globals and entity fields in a loaded progs: every name
// of id's progdefs.h (globalvars_t, entvars_t) resolved once, at load, to a word offset. Mods add
// their own fields and globals after these; a progs that lacks one of them cannot run the game.
#pragma once

#include <cstdint>
#include <string>

#include "common/result.h"
#include "vm/progs.h"

namespace nq::server {

// X(name, type): the system globals, in progdefs.h order. parm1 stands for parm1..parm16, which
// follow it in consecutive words.
#define NQ_SYSTEM_GLOBALS(X)                                                                       \
    X(self, entity)                                                                                \
    X(other, entity)                                                                               \
    X(world, entity) X(time, float_) X(frametime, float_) X(force_retouch, float_)                 \
        X(mapname, string) X(deathmatch, float_) X(coop, float_) X(teamplay, float_) X(            \
            serverflags, float_) X(total_secrets, float_) X(total_monsters, float_)                \
            X(found_secrets, float_) X(killed_monsters, float_) X(parm1, float_) X(                \
                v_forward, vector) X(v_up, vector) X(v_right, vector) X(trace_allsolid, float_)    \
                X(trace_startsolid, float_) X(trace_fraction, float_) X(trace_endpos, vector)      \
                    X(trace_plane_normal, vector) X(trace_plane_dist, float_) X(trace_ent, entity) \
                        X(trace_inopen, float_) X(trace_inwater, float_) X(msg_entity, entity)     \
                            X(main, function) X(StartFrame, function) X(PlayerPreThink, function)  \
                                X(PlayerPostThink, function) X(ClientKill, function)               \
                                    X(ClientConnect, function) X(PutClientInServer, function)      \
                                        X(ClientDisconnect, function) X(SetNewParms, function)     \
                                            X(SetChangeParms, function)

// X(name, type): the system entity fields, in progdefs.h order.
#define NQ_SYSTEM_FIELDS(X)                                                                        \
    X(modelindex, float_)                                                                          \
    X(absmin, vector)                                                                              \
    X(absmax, vector) X(ltime, float_) X(movetype, float_) X(solid, float_) X(origin, vector)      \
        X(oldorigin, vector) X(velocity, vector) X(angles, vector) X(avelocity, vector)            \
            X(punchangle, vector) X(classname, string) X(model, string) X(frame, float_) X(        \
                skin, float_) X(effects, float_) X(mins, vector) X(maxs, vector) X(size, vector)   \
                X(touch, function) X(use, function) X(think, function) X(blocked, function) X(     \
                    nextthink, float_) X(groundentity, entity) X(health, float_) X(frags, float_)  \
                    X(weapon, float_) X(weaponmodel, string) X(weaponframe, float_)                \
                        X(currentammo, float_) X(ammo_shells, float_) X(ammo_nails, float_)        \
                            X(ammo_rockets, float_) X(ammo_cells, float_) X(items, float_)         \
                                X(takedamage, float_) X(chain, entity) X(deadflag, float_) X(      \
                                    view_ofs, vector) X(button0, float_) X(button1, float_)        \
                                    X(button2, float_) X(impulse, float_) X(fixangle, float_) X(   \
                                        v_angle, vector) X(idealpitch, float_) X(netname, string)  \
                                        X(enemy, entity) X(flags, float_) X(colormap, float_) X(   \
                                            team, float_) X(max_health, float_)                    \
                                            X(teleport_time, float_) X(armortype, float_) X(       \
                                                armorvalue, float_) X(waterlevel, float_)          \
                                                X(watertype, float_) X(ideal_yaw, float_) X(       \
                                                    yaw_speed, float_) X(aiment, entity)           \
                                                    X(goalentity, entity) X(spawnflags, float_) X( \
                                                        target, string) X(targetname, string)      \
                                                        X(dmg_take, float_) X(dmg_save, float_) X( \
                                                            dmg_inflictor, entity)                 \
                                                            X(owner, entity) X(movedir, vector) X( \
                                                                message, string) X(sounds, float_) \
                                                                X(noise, string) X(noise1, string) \
                                                                    X(noise2, string)              \
                                                                        X(noise3, string)

struct GlobalOffsets {
#define NQ_DECLARE_OFFSET(name, type) uint32_t name = 0;
    NQ_SYSTEM_GLOBALS(NQ_DECLARE_OFFSET)
};
struct FieldOffsets {
    NQ_SYSTEM_FIELDS(NQ_DECLARE_OFFSET)
#undef NQ_DECLARE_OFFSET
};

struct ProgsLayout {
    GlobalOffsets globals;
    FieldOffsets fields;
    // Optional fields some progs add and the engine honours when present (0 = absent).
    uint32_t field_alpha = 0;
    uint32_t field_gravity = 0;
    uint32_t field_items2 = 0;
};

// Finds every system global and field by name; an error names the first that is missing or
// has the wrong type.
Result<ProgsLayout> resolve_layout(const vm::Progs& progs);

// Quake's constants the engine shares with QuakeC (defs.qc).
namespace qc {
enum MoveType {
    kMoveNone = 0,
    kMoveWalk = 3,
    kMoveStep = 4,
    kMoveFly = 5,
    kMoveToss = 6,
    kMovePush = 7,
    kMoveNoclip = 8,
    kMoveFlyMissile = 9,
    kMoveBounce = 10
};
enum Solid { kSolidNot = 0, kSolidTrigger = 1, kSolidBbox = 2, kSolidSlideBox = 3, kSolidBsp = 4 };
enum Flags {
    kFlFly = 1,
    kFlSwim = 2,
    kFlConveyor = 4,
    kFlClient = 8,
    kFlInWater = 16,
    kFlMonster = 32,
    kFlGodMode = 64,
    kFlNoTarget = 128,
    kFlItem = 256,
    kFlOnGround = 512,
    kFlPartialGround = 1024,
    kFlWaterJump = 2048,
    kFlJumpReleased = 4096
};
enum DeadFlag { kDeadNo = 0, kDeadDying = 1, kDeadDead = 2 };
}  // namespace qc

}  // namespace nq::server

// Quake's builtins #1..#78 (pr_cmds.c's table, by number), on a ServerLevel.
#include "server/builtins.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "server/message_writer.h"
#include "server/monster_move.h"
#include "server/qmath.h"
#include "server/server_messages.h"

namespace nq::server {

namespace {

using vm::Vec3f;
using vm::Vm;

constexpr int kMsgBroadcast = 0, kMsgOne = 1, kMsgAll = 2, kMsgInit = 3;
constexpr float kDamageAim = 2;

ServerLevel& L(void* host) {
    return *static_cast<ServerLevel*>(host);
}
const FieldOffsets& F(void* host) {
    return L(host).layout.fields;
}
const GlobalOffsets& G(void* host) {
    return L(host).layout.globals;
}

uint32_t self_edict(Vm& vm, void* host) {
    const std::optional<uint32_t> e = vm.edict_of(vm.global_word(G(host).self));
    if (!e) vm.fail("self is not an entity");
    return *e;
}

// Every string parameter from `first` on, joined (bprint, sprint, centerprint take several in
// later engines; Quake's progs pass one, which this also handles).
std::string joined_strings(Vm& vm, int first) {
    std::string s;
    for (int i = first; i < vm.argc(); ++i) s += vm.param_string(i);
    return s;
}

void set_min_max_size(Vm& vm, void* host, uint32_t e, const Vec3f& mins, const Vec3f& maxs) {
    for (int i = 0; i < 3; ++i) {
        if (mins[i] > maxs[i]) {
            char text[160];
            std::snprintf(text, sizeof text, "backwards mins/maxs '%g %g %g' '%g %g %g'",
                          double(mins[0]), double(mins[1]), double(mins[2]), double(maxs[0]),
                          double(maxs[1]), double(maxs[2]));
            vm.fail(text);
        }
    }
    vm.set_field_vector(e, F(host).mins, mins);
    vm.set_field_vector(e, F(host).maxs, maxs);
    vm.set_field_vector(e, F(host).size, vsub(maxs, mins));
    L(host).world.link(e, false);
}

// ---- #1..#20

void makevectors(Vm& vm, void* host) {
    const Basis b = angle_vectors(vm.param_vector(0));
    vm.set_global_vector(G(host).v_forward, b.forward);
    vm.set_global_vector(G(host).v_right, b.right);
    vm.set_global_vector(G(host).v_up, b.up);
}

void setorigin(Vm& vm, void* host) {
    const uint32_t e = vm.param_edict(0);
    vm.set_field_vector(e, F(host).origin, vm.param_vector(1));
    L(host).world.link(e, false);
}

void setmodel(Vm& vm, void* host) {
    ServerLevel& level = L(host);
    const uint32_t e = vm.param_edict(0);
    const std::string_view name = vm.param_string(1);
    const int index = level.model_index(name);
    if (index < 0) vm.fail("no precache: " + std::string(name));
    vm.set_field_int(e, F(host).model, vm.param_int(1));
    vm.set_field_float(e, F(host).modelindex, float(index));
    const CollisionModel& model = level.collision[size_t(index)];
    if (model.bsp && model.submodel < model.bsp->models.size()) {
        // Quake loads a brush model's bounds spread by a unit each way (some compilers write
        // zero-thickness trigger boxes whose stored mins pass their maxs).
        const BspModel& b = model.bsp->models[model.submodel];
        set_min_max_size(vm, host, e, vsub(b.mins, {1, 1, 1}), vadd(b.maxs, {1, 1, 1}));
    } else if (index > 0) {
        set_min_max_size(vm, host, e, {-16, -16, -16}, {16, 16, 16});  // Quake's alias box
    } else {
        set_min_max_size(vm, host, e, {0, 0, 0}, {0, 0, 0});
    }
}

void setsize(Vm& vm, void* host) {
    set_min_max_size(vm, host, vm.param_edict(0), vm.param_vector(1), vm.param_vector(2));
}

void break_(Vm& vm, void* host) {
    L(host).host.print("break statement\n");
}

void random(Vm& vm, void* host) {
    vm.return_float(L(host).random.next());
}

void sound(Vm& vm, void* host) {
    write_sound(L(host), vm.param_edict(0), int(vm.param_float(1)), vm.param_string(2),
                vm.param_float(3), vm.param_float(4));
}

void normalize(Vm& vm, void*) {
    const Vec3f v = vm.param_vector(0);
    const float len = vlength(v);
    vm.return_vector(len == 0 ? Vec3f{0, 0, 0} : vscale(v, 1.0f / len));
}

void error(Vm& vm, void* host) {
    vm.fail("error: " + joined_strings(vm, 0));
}

void objerror(Vm& vm, void* host) {
    const uint32_t self = self_edict(vm, host);
    ServerLevel& level = L(host);
    const std::string text = joined_strings(vm, 0);
    level.world.unlink(self);
    level.edicts.free(vm, level.layout, self, level.game.time);
    vm.fail("objerror: " + text);
}

void vlen(Vm& vm, void*) {
    vm.return_float(vlength(vm.param_vector(0)));
}

float yaw_of(const Vec3f& v) {
    if (v[0] == 0 && v[1] == 0) return 0;
    float yaw = std::trunc(std::atan2(v[1], v[0]) * 180 / float(M_PI));
    return yaw < 0 ? yaw + 360 : yaw;
}

void vectoyaw(Vm& vm, void*) {
    vm.return_float(yaw_of(vm.param_vector(0)));
}

void spawn(Vm& vm, void* host) {
    ServerLevel& level = L(host);
    const std::optional<uint32_t> e = level.edicts.alloc(vm, level.game.time);
    if (!e) vm.fail("no free edicts (" + std::to_string(vm.max_edicts()) + ")");
    vm.return_edict(*e);
}

void remove(Vm& vm, void* host) {
    ServerLevel& level = L(host);
    const uint32_t e = vm.param_edict(0);
    if (e == 0 || level.is_client(e)) {
        level.host.debug_print("remove: tried to remove the world or a client\n");
        return;
    }
    level.world.unlink(e);
    level.edicts.free(vm, level.layout, e, level.game.time);
}

void set_trace_globals(Vm& vm, void* host, const MoveTrace& t) {
    const GlobalOffsets& g = G(host);
    vm.set_global_float(g.trace_allsolid, t.all_solid);
    vm.set_global_float(g.trace_startsolid, t.start_solid);
    vm.set_global_float(g.trace_fraction, t.fraction);
    vm.set_global_float(g.trace_inwater, t.in_water);
    vm.set_global_float(g.trace_inopen, t.in_open);
    vm.set_global_vector(g.trace_endpos, t.end_pos);
    vm.set_global_vector(g.trace_plane_normal, t.plane_normal);
    vm.set_global_float(g.trace_plane_dist, t.plane_dist);
    vm.set_global_word(g.trace_ent, t.entity ? vm.entity_value(*t.entity) : 0);
}

void traceline(Vm& vm, void* host) {
    const Vec3f start = vm.param_vector(0), end = vm.param_vector(1);
    const MoveKind kind = vm.param_float(2) != 0 ? MoveKind::no_monsters : MoveKind::normal;
    const uint32_t pass = vm.param_edict(3);
    set_trace_globals(vm, host, L(host).world.move(start, {0, 0, 0}, {0, 0, 0}, end, kind, pass));
}

// The local client, if it stands where `self` can see it (Quake's PVS test from self's eyes).
void checkclient(Vm& vm, void* host) {
    ServerLevel& level = L(host);
    const FieldOffsets& f = F(host);
    const uint32_t client = 1;
    if (!level.client.spawned || level.edicts.is_free(client) ||
        vm.field_float(client, f.health) <= 0 ||
        (int(vm.field_float(client, f.flags)) & qc::kFlNoTarget)) {
        return vm.return_edict(0);
    }
    const uint32_t self = self_edict(vm, host);
    const Vec3f eye = vadd(vm.field_vector(self, f.origin), vm.field_vector(self, f.view_ofs));
    const Vec3f client_eye =
        vadd(vm.field_vector(client, f.origin), vm.field_vector(client, f.view_ofs));
    const std::span<const uint8_t> row = level.pvs_of(client_eye);
    vm.return_edict(row.empty() || pvs_contains(row, leaf_at(*level.bsp, eye)) ? client : 0);
}

void find(Vm& vm, void* host) {
    const uint32_t start = vm.param_edict(0);
    const uint32_t field = uint32_t(vm.param_int(1));
    const std::string_view wanted = vm.param_string(2);
    for (uint32_t e = start + 1; e < vm.num_edicts(); ++e) {
        if (L(host).edicts.is_free(e)) continue;
        if (vm.string(vm.field_int(e, field)) == wanted) return vm.return_edict(e);
    }
    vm.return_edict(0);
}

void precache(Vm& vm, void* host, std::vector<std::string>& list, bool model) {
    ServerLevel& level = L(host);
    vm.return_int(vm.param_int(0));
    const std::string_view name = vm.param_string(0);
    if (name.empty()) vm.fail("precache of an empty name");
    if (std::find(list.begin(), list.end(), name) != list.end()) return;
    if (!level.loading)
        vm.fail("precache can only be done in spawn functions (" + std::string(name) + ")");
    list.emplace_back(name);
    if (!model) return;
    level.collision.push_back(load_collision_model(level, name));
    level.world.set_model(level.collision.size() - 1, level.collision.back());
}

void precache_sound(Vm& vm, void* host) {
    precache(vm, host, L(host).sound_names, false);
}
void precache_model(Vm& vm, void* host) {
    precache(vm, host, L(host).model_names, true);
}

uint32_t client_param(Vm& vm, void* host, int i) {
    const uint32_t e = vm.param_edict(i);
    if (!L(host).is_client(e)) vm.fail("parameter is not a client");
    return e;
}

void stuffcmd(Vm& vm, void* host) {
    client_param(vm, host, 0);
    write_client_text(L(host), protocol::svc_stufftext, vm.param_string(1));
}

void findradius(Vm& vm, void* host) {
    const Vec3f org = vm.param_vector(0);
    const float radius = vm.param_float(1);
    const FieldOffsets& f = F(host);
    uint32_t chain = 0;
    for (uint32_t e = 1; e < vm.num_edicts(); ++e) {
        if (L(host).edicts.is_free(e) || int(vm.field_float(e, f.solid)) == qc::kSolidNot) continue;
        const Vec3f centre =
            vadd(vm.field_vector(e, f.origin),
                 vscale(vadd(vm.field_vector(e, f.mins), vm.field_vector(e, f.maxs)), 0.5f));
        if (vlength(vsub(org, centre)) > radius) continue;
        vm.set_field_int(e, f.chain, int32_t(vm.entity_value(chain)));
        chain = e;
    }
    vm.return_edict(chain);
}

void bprint(Vm& vm, void* host) {
    write_client_text(L(host), protocol::svc_print, joined_strings(vm, 0));
}

void sprint(Vm& vm, void* host) {
    client_param(vm, host, 0);
    write_client_text(L(host), protocol::svc_print, joined_strings(vm, 1));
}

void dprint(Vm& vm, void* host) {
    L(host).host.debug_print(joined_strings(vm, 0));
}

// Quake's number formats: whole numbers plainly, others with one decimal.
void ftos(Vm& vm, void*) {
    const float v = vm.param_float(0);
    char text[64];
    if (std::isfinite(v) && v == std::trunc(v) && std::fabs(v) < 2e9f) {
        std::snprintf(text, sizeof text, "%d", int(v));
    } else {
        std::snprintf(text, sizeof text, "%5.1f", double(v));
    }
    vm.return_temp_string(text);
}

void vtos(Vm& vm, void*) {
    const Vec3f v = vm.param_vector(0);
    char text[128];
    std::snprintf(text, sizeof text, "'%5.1f %5.1f %5.1f'", double(v[0]), double(v[1]),
                  double(v[2]));
    vm.return_temp_string(text);
}

void coredump(Vm& vm, void* host) {
    L(host).host.print("coredump: " + std::to_string(vm.num_edicts()) + " edicts\n");
}

void traceon_off(Vm&, void*) {}

void eprint(Vm& vm, void* host) {
    const uint32_t e = vm.param_edict(0);
    const vm::Progs& progs = vm.progs();
    std::string text = "EDICT " + std::to_string(e) + ":\n";
    for (const vm::Def& d : progs.field_defs) {
        const std::string_view name = progs.string_at(d.name);
        if (name.empty() || (name.size() > 2 && name[name.size() - 2] == '_')) continue;
        const int32_t word = vm.field_int(e, d.offset);
        if (word == 0) continue;
        text += std::string(name) + " ";
        if (d.def_type() == vm::DefType::string) {
            text += std::string(vm.string_or_empty(word));
        } else {
            text += std::to_string(vm.field_float(e, d.offset));
        }
        text += "\n";
    }
    L(host).host.print(text);
}

// ---- #32..#51

void walkmove(Vm& vm, void* host) {
    ServerLevel& level = L(host);
    const uint32_t self = self_edict(vm, host);
    // Touch functions may run in the move and change `self`; the caller keeps its own.
    const uint32_t saved_self = vm.global_word(G(host).self);
    const bool moved = walk_move(level.game, self, vm.param_float(0), vm.param_float(1), true);
    vm.set_global_word(G(host).self, saved_self);
    vm.return_float(moved ? 1 : 0);
}

void droptofloor(Vm& vm, void* host) {
    vm.return_float(drop_to_floor(L(host).game, self_edict(vm, host)) ? 1 : 0);
}

void lightstyle(Vm& vm, void* host) {
    set_lightstyle(L(host), int(vm.param_float(0)), vm.param_string(1));
}

void rint(Vm& vm, void*) {
    const float f = vm.param_float(0);
    vm.return_float(f > 0 ? std::trunc(f + 0.5f) : std::trunc(f - 0.5f));
}

void floor_(Vm& vm, void*) {
    vm.return_float(std::floor(vm.param_float(0)));
}
void ceil_(Vm& vm, void*) {
    vm.return_float(std::ceil(vm.param_float(0)));
}
void fabs_(Vm& vm, void*) {
    vm.return_float(std::fabs(vm.param_float(0)));
}

void checkbottom(Vm& vm, void* host) {
    vm.return_float(check_bottom(L(host).game, vm.param_edict(0)) ? 1 : 0);
}

void pointcontents(Vm& vm, void* host) {
    vm.return_float(float(L(host).world.point_contents(vm.param_vector(0))));
}

// Quake's autoaim: straight ahead if that hits something; otherwise the target nearest the
// crosshair within sv_aim's cone, pitch only.
void aim(Vm& vm, void* host) {
    ServerLevel& level = L(host);
    const FieldOffsets& f = F(host);
    const uint32_t shooter = vm.param_edict(0);
    const Vec3f start = vadd(vm.field_vector(shooter, f.origin), {0, 0, 20});
    const Vec3f forward = vm.global_vector(G(host).v_forward);
    MoveTrace tr = level.world.move(start, {0, 0, 0}, {0, 0, 0}, vmad(start, 2048, forward),
                                    MoveKind::normal, shooter);
    if (tr.entity && *tr.entity != 0 && vm.field_float(*tr.entity, f.takedamage) == kDamageAim) {
        return vm.return_vector(forward);
    }
    const float cone = level.host.cvar_value("sv_aim");
    float best = cone;
    std::optional<Vec3f> best_dir;
    for (uint32_t e = 1; e < vm.num_edicts(); ++e) {
        if (e == shooter || level.edicts.is_free(e)) continue;
        if (vm.field_float(e, f.takedamage) != kDamageAim) continue;
        const Vec3f centre =
            vadd(vm.field_vector(e, f.origin),
                 vscale(vadd(vm.field_vector(e, f.mins), vm.field_vector(e, f.maxs)), 0.5f));
        Vec3f dir = vsub(centre, start);
        const float len = vlength(dir);
        if (len == 0) continue;
        dir = vscale(dir, 1 / len);
        const float d = vdot(dir, forward);
        if (d < best) continue;
        tr = level.world.move(start, {0, 0, 0}, {0, 0, 0}, centre, MoveKind::normal, shooter);
        if (tr.entity && *tr.entity == e) {
            best = d;
            best_dir = dir;
        }
    }
    if (!best_dir) return vm.return_vector(forward);
    Vec3f dir = forward;
    dir[2] = 0;
    const float flat = vlength(dir);
    dir = flat > 0 ? vscale(dir, 1 / flat) : dir;
    dir[2] = (*best_dir)[2];
    const float len = vlength(dir);
    vm.return_vector(len > 0 ? vscale(dir, 1 / len) : forward);
}

void cvar(Vm& vm, void* host) {
    vm.return_float(L(host).host.cvar_value(vm.param_string(0)));
}

void localcmd(Vm& vm, void* host) {
    L(host).host.add_command(vm.param_string(0));
}

void nextent(Vm& vm, void* host) {
    for (uint32_t e = vm.param_edict(0) + 1; e < vm.num_edicts(); ++e) {
        if (!L(host).edicts.is_free(e)) return vm.return_edict(e);
    }
    vm.return_edict(0);
}

void particle(Vm& vm, void* host) {
    write_particle(L(host), vm.param_vector(0), vm.param_vector(1), int(vm.param_float(2)),
                   int(vm.param_float(3)));
}

void changeyaw(Vm& vm, void* host) {
    change_yaw(L(host).game, self_edict(vm, host));
}

void vectoangles(Vm& vm, void*) {
    const Vec3f v = vm.param_vector(0);
    float yaw = 0, pitch = 0;
    if (v[0] == 0 && v[1] == 0) {
        pitch = v[2] > 0 ? 90 : 270;
    } else {
        yaw = yaw_of(v);
        const float forward = std::sqrt(v[0] * v[0] + v[1] * v[1]);
        pitch = std::trunc(std::atan2(v[2], forward) * 180 / float(M_PI));
        if (pitch < 0) pitch += 360;
    }
    vm.return_vector({pitch, yaw, 0});
}

// ---- #52..#59: QuakeC writing raw messages

std::vector<uint8_t>& destination(Vm& vm, void* host) {
    ServerLevel& level = L(host);
    switch (int(vm.param_float(0))) {
        case kMsgBroadcast:
            return level.datagram;
        case kMsgOne: {
            const std::optional<uint32_t> e = vm.edict_of(vm.global_word(G(host).msg_entity));
            if (!e || !level.is_client(*e)) vm.fail("WriteDest: msg_entity is not a client");
            return level.client.message;
        }
        case kMsgAll:
            return level.reliable_datagram;
        case kMsgInit:
            return level.signon;
        default:
            vm.fail("WriteDest: bad destination");
    }
}

MessageWriter writer(Vm& vm, void* host) {
    return MessageWriter(destination(vm, host), L(host).protocol);
}

void write_byte(Vm& vm, void* host) {
    writer(vm, host).byte(int(vm.param_float(1)));
}
void write_char(Vm& vm, void* host) {
    writer(vm, host).chr(int(vm.param_float(1)));
}
void write_short(Vm& vm, void* host) {
    writer(vm, host).shrt(int(vm.param_float(1)));
}
void write_long(Vm& vm, void* host) {
    writer(vm, host).lng(int32_t(vm.param_float(1)));
}
void write_coord(Vm& vm, void* host) {
    writer(vm, host).coord(vm.param_float(1));
}
void write_angle(Vm& vm, void* host) {
    writer(vm, host).angle(vm.param_float(1));
}
void write_string(Vm& vm, void* host) {
    writer(vm, host).string(vm.param_string(1));
}
void write_entity(Vm& vm, void* host) {
    writer(vm, host).shrt(int(vm.param_edict(1)));
}

// ---- #67..#78

void movetogoal(Vm& vm, void* host) {
    const uint32_t saved_self = vm.global_word(G(host).self);
    move_to_goal(L(host).game, self_edict(vm, host), vm.param_float(0), L(host).random);
    vm.set_global_word(G(host).self, saved_self);
}

void precache_file(Vm& vm, void*) {
    vm.return_int(vm.param_int(0));
}

void makestatic(Vm& vm, void* host) {
    ServerLevel& level = L(host);
    const uint32_t e = vm.param_edict(0);
    write_static_entity(level, e);
    level.world.unlink(e);
    level.edicts.free(vm, level.layout, e, level.game.time);
}

void changelevel(Vm& vm, void* host) {
    ServerLevel& level = L(host);
    if (level.pending_changelevel) return;  // the first one wins, as in Quake
    level.pending_changelevel = std::string(vm.param_string(0));
}

void cvar_set(Vm& vm, void* host) {
    L(host).host.set_cvar(vm.param_string(0), vm.param_string(1));
}

void centerprint(Vm& vm, void* host) {
    client_param(vm, host, 0);
    write_client_text(L(host), protocol::svc_centerprint, joined_strings(vm, 1));
}

void ambientsound(Vm& vm, void* host) {
    write_static_sound(L(host), vm.param_vector(0), vm.param_string(1), vm.param_float(2),
                       vm.param_float(3));
}

void setspawnparms(Vm& vm, void* host) {
    const uint32_t e = vm.param_edict(0);
    if (!L(host).is_client(e)) vm.fail("setspawnparms: entity is not a client");
    const std::array<float, kNumSpawnParms>& parms = L(host).client.spawn_parms;
    for (int i = 0; i < kNumSpawnParms; ++i) {
        vm.set_global_float(G(host).parm1 + uint32_t(i), parms[size_t(i)]);
    }
}

void fixme(Vm& vm, void*) {
    vm.fail("unimplemented builtin");
}

constexpr std::array<vm::Builtin, 79> kBuiltins = {{
    {"fixme", fixme},
    {"makevectors", makevectors},
    {"setorigin", setorigin},
    {"setmodel", setmodel},
    {"setsize", setsize},
    {"fixme", fixme},
    {"break", break_},
    {"random", random},
    {"sound", sound},
    {"normalize", normalize},
    {"error", error},
    {"objerror", objerror},
    {"vlen", vlen},
    {"vectoyaw", vectoyaw},
    {"spawn", spawn},
    {"remove", remove},
    {"traceline", traceline},
    {"checkclient", checkclient},
    {"find", find},
    {"precache_sound", precache_sound},
    {"precache_model", precache_model},
    {"stuffcmd", stuffcmd},
    {"findradius", findradius},
    {"bprint", bprint},
    {"sprint", sprint},
    {"dprint", dprint},
    {"ftos", ftos},
    {"vtos", vtos},
    {"coredump", coredump},
    {"traceon", traceon_off},
    {"traceoff", traceon_off},
    {"eprint", eprint},
    {"walkmove", walkmove},
    {"fixme", fixme},
    {"droptofloor", droptofloor},
    {"lightstyle", lightstyle},
    {"rint", rint},
    {"floor", floor_},
    {"ceil", ceil_},
    {"fixme", fixme},
    {"checkbottom", checkbottom},
    {"pointcontents", pointcontents},
    {"fixme", fixme},
    {"fabs", fabs_},
    {"aim", aim},
    {"cvar", cvar},
    {"localcmd", localcmd},
    {"nextent", nextent},
    {"particle", particle},
    {"changeyaw", changeyaw},
    {"fixme", fixme},
    {"vectoangles", vectoangles},
    {"WriteByte", write_byte},
    {"WriteChar", write_char},
    {"WriteShort", write_short},
    {"WriteLong", write_long},
    {"WriteCoord", write_coord},
    {"WriteAngle", write_angle},
    {"WriteString", write_string},
    {"WriteEntity", write_entity},
    {"fixme", fixme},
    {"fixme", fixme},
    {"fixme", fixme},
    {"fixme", fixme},
    {"fixme", fixme},
    {"fixme", fixme},
    {"fixme", fixme},
    {"movetogoal", movetogoal},
    {"precache_file", precache_file},
    {"makestatic", makestatic},
    {"changelevel", changelevel},
    {"fixme", fixme},
    {"cvar_set", cvar_set},
    {"centerprint", centerprint},
    {"ambientsound", ambientsound},
    {"precache_model2", precache_model},
    {"precache_sound2", precache_sound},
    {"precache_file2", precache_file},
    {"setspawnparms", setspawnparms},
}};

}  // namespace

std::span<const vm::Builtin> game_builtins() {
    return kBuiltins;
}

}  // namespace nq::server

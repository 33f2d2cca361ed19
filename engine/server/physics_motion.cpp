#include "server/physics_motion.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "formats/bsp.h"
#include "server/qmath.h"
#include "server/server_host.h"

namespace nq::server::physics {

namespace {

bool is_liquid(int32_t contents) {
    return contents <= bsp_contents::water;
}

Vec3f cross(const Vec3f& a, const Vec3f& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

bool is_zero(const Vec3f& v) {
    return v[0] == 0 && v[1] == 0 && v[2] == 0;
}

void warn_nan(GameState& game, uint32_t edict, ServerHost* host, const char* what) {
    if (!host) return;
    const std::string_view name =
        game.vm.string_or_empty(game.vm.field_int(edict, game.f().classname));
    host->print("Got a NaN " + std::string(what) + " on " + std::string(name) + "\n");
}

// Which entities a pushed entity collides with: missiles hit monsters with a wider box,
// triggers and non-solids only clip against brush models.
MoveKind push_kind(const GameState& game, uint32_t edict) {
    if (movetype(game, edict) == qc::kMoveFlyMissile) return MoveKind::missile;
    const int s = solid(game, edict);
    if (s == qc::kSolidTrigger || s == qc::kSolidNot) return MoveKind::no_monsters;
    return MoveKind::normal;
}

}  // namespace

int flags(const GameState& game, uint32_t edict) {
    return int(game.vm.field_float(edict, game.f().flags));
}

void set_flags(GameState& game, uint32_t edict, int value) {
    game.vm.set_field_float(edict, game.f().flags, float(value));
}

uint32_t edict_field(const GameState& game, uint32_t edict, uint32_t field) {
    return game.vm.edict_of(uint32_t(game.vm.field_int(edict, field))).value_or(0);
}

void set_edict_field(GameState& game, uint32_t edict, uint32_t field, uint32_t target) {
    game.vm.set_field_int(edict, field, int32_t(game.vm.entity_value(target)));
}

int movetype(const GameState& game, uint32_t edict) {
    return int(game.vm.field_float(edict, game.f().movetype));
}

int solid(const GameState& game, uint32_t edict) {
    return int(game.vm.field_float(edict, game.f().solid));
}

bool call_qc(GameState& game, int32_t function, uint32_t self, uint32_t other) {
    game.vm.set_global_word(game.g().self, game.vm.entity_value(self));
    game.vm.set_global_word(game.g().other, game.vm.entity_value(other));
    return game.vm.execute(function);
}

bool run_think(GameState& game, uint32_t edict) {
    const FieldOffsets& f = game.f();
    const float think_time = game.vm.field_float(edict, f.nextthink);
    if (think_time <= 0 || double(think_time) > game.time + double(game.frame_time)) return true;
    // A think set in the past (by a trigger's local time) runs now, never earlier.
    const double when = std::max(double(think_time), game.time);
    game.vm.set_field_float(edict, f.nextthink, 0);
    game.vm.set_global_float(game.g().time, float(when));
    const bool ok = call_qc(game, game.vm.field_int(edict, f.think), edict, 0);
    return ok && !game.edicts.is_free(edict);
}

void impact(GameState& game, uint32_t e1, uint32_t e2) {
    vm::Vm& vm = game.vm;
    const FieldOffsets& f = game.f();
    const uint32_t old_self = vm.global_word(game.g().self);
    const uint32_t old_other = vm.global_word(game.g().other);
    vm.set_global_float(game.g().time, float(game.time));
    for (auto [self, other] : {std::array{e1, e2}, std::array{e2, e1}}) {
        const int32_t touch = vm.field_int(self, f.touch);
        if (touch && solid(game, self) != qc::kSolidNot) call_qc(game, touch, self, other);
    }
    vm.set_global_word(game.g().self, old_self);
    vm.set_global_word(game.g().other, old_other);
}

void start_sound(GameState& game, uint32_t edict, std::string_view sample) {
    // Quake's volume 255 of 255, normal attenuation, channel 0 (auto).
    if (game.sounds) game.sounds->start_sound(edict, 0, sample, 1.0f, 1.0f);
}

void check_velocity(GameState& game, uint32_t edict, ServerHost* host) {
    const FieldOffsets& f = game.f();
    Vec3f velocity = game.vm.field_vector(edict, f.velocity);
    Vec3f origin = game.vm.field_vector(edict, f.origin);
    const float limit = game.settings.max_velocity;
    for (int i = 0; i < 3; ++i) {
        if (std::isnan(velocity[i])) {
            warn_nan(game, edict, host, "velocity");
            velocity[i] = 0;
        }
        if (std::isnan(origin[i])) {
            warn_nan(game, edict, host, "origin");
            origin[i] = 0;
        }
        velocity[i] = std::clamp(velocity[i], -limit, limit);
    }
    game.vm.set_field_vector(edict, f.velocity, velocity);
    game.vm.set_field_vector(edict, f.origin, origin);
}

void add_gravity(GameState& game, uint32_t edict) {
    float scale = 1;
    if (game.layout.field_gravity) {
        const float own = game.vm.field_float(edict, game.layout.field_gravity);
        if (own != 0) scale = own;
    }
    Vec3f velocity = game.vm.field_vector(edict, game.f().velocity);
    velocity[2] -= scale * game.settings.gravity * game.frame_time;
    game.vm.set_field_vector(edict, game.f().velocity, velocity);
}

int clip_velocity(const Vec3f& in, const Vec3f& normal, Vec3f& out, float overbounce) {
    int blocked = 0;
    if (normal[2] > 0) blocked |= kBlockedFloor;
    if (normal[2] == 0) blocked |= kBlockedStep;
    const float backoff = vdot(in, normal) * overbounce;
    for (int i = 0; i < 3; ++i) {
        out[i] = in[i] - normal[i] * backoff;
        if (out[i] > -kStopEpsilon && out[i] < kStopEpsilon) out[i] = 0;
    }
    return blocked;
}

namespace {

// fly_move's choice after hitting its planes: slide along one of them, or along the crease of
// two, or stop. Returns false when the entity must stop.
bool slide_along_planes(const Vec3f* planes, int count, const Vec3f& original, Vec3f& velocity) {
    for (int i = 0; i < count; ++i) {
        Vec3f slid;
        clip_velocity(original, planes[i], slid, 1);
        bool fits = true;
        for (int j = 0; j < count && fits; ++j) {
            if (j != i && vdot(slid, planes[j]) < 0) fits = false;
        }
        if (fits) {
            velocity = slid;
            return true;
        }
    }
    if (count != 2) return false;
    const Vec3f dir = cross(planes[0], planes[1]);
    velocity = vscale(dir, vdot(dir, velocity));
    return true;
}

}  // namespace

int fly_move(GameState& game, uint32_t edict, float time, MoveTrace* step_trace) {
    vm::Vm& vm = game.vm;
    const FieldOffsets& f = game.f();
    const Vec3f primal_velocity = vm.field_vector(edict, f.velocity);
    Vec3f original_velocity = primal_velocity;
    std::array<Vec3f, kMaxClipPlanes> planes{};
    int num_planes = 0;
    int blocked = 0;
    float time_left = time;
    for (int bump = 0; bump < 4; ++bump) {
        Vec3f velocity = vm.field_vector(edict, f.velocity);
        if (is_zero(velocity)) break;
        const Vec3f origin = vm.field_vector(edict, f.origin);
        const Vec3f end = vmad(origin, time_left, velocity);
        const MoveTrace trace =
            game.world.move(origin, vm.field_vector(edict, f.mins), vm.field_vector(edict, f.maxs),
                            end, MoveKind::normal, edict);
        if (trace.all_solid) {  // trapped inside another solid
            vm.set_field_vector(edict, f.velocity, {0, 0, 0});
            return kBlockedFloor | kBlockedStep;
        }
        if (trace.fraction > 0) {  // covered some distance: the planes so far are behind us
            vm.set_field_vector(edict, f.origin, trace.end_pos);
            original_velocity = velocity;
            num_planes = 0;
        }
        if (trace.fraction == 1) break;
        const uint32_t hit = trace.entity.value_or(0);
        if (trace.plane_normal[2] > 0.7f) {
            blocked |= kBlockedFloor;
            if (solid(game, hit) == qc::kSolidBsp) {
                set_flags(game, edict, flags(game, edict) | qc::kFlOnGround);
                set_edict_field(game, edict, f.groundentity, hit);
            }
        }
        if (trace.plane_normal[2] == 0) {
            blocked |= kBlockedStep;
            if (step_trace) *step_trace = trace;
        }
        impact(game, edict, hit);
        if (game.edicts.is_free(edict)) break;  // removed by its touch
        time_left -= time_left * trace.fraction;
        if (num_planes >= kMaxClipPlanes) {
            vm.set_field_vector(edict, f.velocity, {0, 0, 0});
            return kBlockedFloor | kBlockedStep;
        }
        planes[size_t(num_planes++)] = trace.plane_normal;
        velocity = vm.field_vector(edict, f.velocity);
        if (!slide_along_planes(planes.data(), num_planes, original_velocity, velocity)) {
            vm.set_field_vector(edict, f.velocity, {0, 0, 0});
            return kBlockedTrapped;
        }
        // Turned against where it first went: stop dead, so sloping corners cannot jitter.
        if (vdot(velocity, primal_velocity) <= 0) velocity = {0, 0, 0};
        vm.set_field_vector(edict, f.velocity, velocity);
        if (is_zero(velocity)) return blocked;
    }
    return blocked;
}

MoveTrace push_entity(GameState& game, uint32_t edict, const Vec3f& push) {
    vm::Vm& vm = game.vm;
    const FieldOffsets& f = game.f();
    const Vec3f origin = vm.field_vector(edict, f.origin);
    const MoveTrace trace =
        game.world.move(origin, vm.field_vector(edict, f.mins), vm.field_vector(edict, f.maxs),
                        vadd(origin, push), push_kind(game, edict), edict);
    vm.set_field_vector(edict, f.origin, trace.end_pos);
    game.world.link(edict, true);
    if (trace.entity) impact(game, edict, *trace.entity);
    return trace;
}

void check_water_transition(GameState& game, uint32_t edict) {
    vm::Vm& vm = game.vm;
    const FieldOffsets& f = game.f();
    const int32_t contents = game.world.point_contents(vm.field_vector(edict, f.origin));
    const float old_type = vm.field_float(edict, f.watertype);
    if (old_type == 0) {  // just spawned here
        vm.set_field_float(edict, f.watertype, float(contents));
        vm.set_field_float(edict, f.waterlevel, 1);
        return;
    }
    if (is_liquid(contents)) {
        if (old_type == float(bsp_contents::empty)) start_sound(game, edict, "misc/h2ohit1.wav");
        vm.set_field_float(edict, f.watertype, float(contents));
        vm.set_field_float(edict, f.waterlevel, 1);
    } else {
        if (old_type != float(bsp_contents::empty)) start_sound(game, edict, "misc/h2ohit1.wav");
        vm.set_field_float(edict, f.watertype, float(bsp_contents::empty));
        // Quake stores the contents here, not a level; QuakeC only tests it for zero.
        vm.set_field_float(edict, f.waterlevel, float(contents));
    }
}

bool check_water(GameState& game, uint32_t edict) {
    vm::Vm& vm = game.vm;
    const FieldOffsets& f = game.f();
    const Vec3f origin = vm.field_vector(edict, f.origin);
    const Vec3f mins = vm.field_vector(edict, f.mins);
    const Vec3f maxs = vm.field_vector(edict, f.maxs);
    vm.set_field_float(edict, f.waterlevel, 0);
    vm.set_field_float(edict, f.watertype, float(bsp_contents::empty));
    // Feet, waist, eyes.
    Vec3f point = {origin[0], origin[1], origin[2] + mins[2] + 1};
    int32_t contents = game.world.point_contents(point);
    if (!is_liquid(contents)) return false;
    vm.set_field_float(edict, f.watertype, float(contents));
    vm.set_field_float(edict, f.waterlevel, 1);
    point[2] = origin[2] + (mins[2] + maxs[2]) * 0.5f;
    if (!is_liquid(game.world.point_contents(point))) return false;
    vm.set_field_float(edict, f.waterlevel, 2);
    point[2] = origin[2] + vm.field_vector(edict, f.view_ofs)[2];
    if (is_liquid(game.world.point_contents(point))) vm.set_field_float(edict, f.waterlevel, 3);
    return true;
}

}  // namespace nq::server::physics

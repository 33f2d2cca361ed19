// The server's collision world (engine/server/world.h): linking and abs boxes, traces against the
// map and against entities, trigger touching, PVS leafs. Expected values come from the map's own
// hull queries (trace_hull, point_contents, leaf_at) or from box geometry worked out by hand.
// Edicts are made by hand in a small assembled progs that declares what the world uses (with
// touch functions that count), or in LibreQuake's progs.dat through its resolved layout.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <random>
#include <stdexcept>

#include "common/file_io.h"
#include "formats/bsp.h"
#include "formats/entities.h"
#include "server/edict_pool.h"
#include "server/progs_layout.h"
#include "server/world.h"
#include "support/allocation_counter.h"
#include "support/synth_progs.h"
#include "support/test_data.h"
#include "vm/opcodes.h"
#include "vm/progs.h"
#include "vm/vm.h"

namespace nq::server {
namespace {

using test::SynthProgs;
using vm::DefType;
using vm::Vec3f;

constexpr float kDistEpsilon = 0.03125f;  // how far Quake's traces stop short of a plane
const Vec3f kZero{0, 0, 0};
const Vec3f kPlayerMins{-16, -16, -24};
const Vec3f kPlayerMaxs{16, 16, 32};

Vec3f add(const Vec3f& a, const Vec3f& b) {
    return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
Vec3f sub(const Vec3f& a, const Vec3f& b) {
    return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

std::shared_ptr<const Bsp> load_map(const std::string& name) {
    static std::map<std::string, std::shared_ptr<const Bsp>> cache;
    if (auto it = cache.find(name); it != cache.end()) return it->second;
    const std::string path = test::lq1_dir() + "/maps/" + name;
    auto bytes = read_file(path);
    if (!bytes) throw std::runtime_error(bytes.error().to_string());
    auto bsp = parse_bsp(*bytes, name);
    if (!bsp) throw std::runtime_error(bsp.error().to_string());
    return cache[name] = std::make_shared<const Bsp>(std::move(*bsp));
}

Vec3f player_start(const Bsp& bsp) {
    auto ents = parse_entities(bsp.entities, bsp.name);
    if (!ents) throw std::runtime_error(ents.error().to_string());
    const auto starts = find_entities(*ents, "info_player_start");
    if (starts.empty()) throw std::runtime_error(bsp.name + ": no info_player_start");
    const auto origin = find_vec3(*starts.front(), "origin");
    if (!origin) throw std::runtime_error(bsp.name + ": info_player_start without origin");
    return *origin;
}

// The collision models a level of `bsp` would have: [1] the world, [2..] its submodels *1, *2...
std::vector<CollisionModel> level_models(const Bsp& bsp) {
    std::vector<CollisionModel> models(1);
    for (size_t i = 0; i < bsp.models.size(); ++i) models.push_back({&bsp, i});
    return models;
}

// ---- a VM with edicts ----

struct Env;
Env& env_of(void* host);

// Builtin #1 (the test's remove): unlinks and clears `victim`. Builtin #2: moves `other` to
// `nested_target` and relinks it with touches, as walkmove from inside a touch function would.
void remove_victim(vm::Vm& vm, void* host);
void nested_relink(vm::Vm& vm, void* host);
const vm::Builtin kBuiltins[] = {{}, {"remove_victim", remove_victim}, {"nested", nested_relink}};

struct Env {
    std::unique_ptr<vm::Vm> vm;
    ProgsLayout layout;
    std::unique_ptr<World> world;
    // Assembled progs only: the counting touch function's globals, and the touch functions.
    uint32_t touch_count = 0, last_self = 0, last_other = 0;
    int32_t count_touch = 0, remove_touch = 0, nested_touch = 0;
    uint32_t victim = 0;
    Vec3f nested_target{};

    const FieldOffsets& f() const { return layout.fields; }

    uint32_t spawn(int solid, const Vec3f& origin, const Vec3f& mins, const Vec3f& maxs) {
        const uint32_t e = vm->num_edicts();
        vm->set_num_edicts(e + 1);
        vm->clear_edict(e);
        vm->set_field_float(e, f().solid, float(solid));
        vm->set_field_vector(e, f().origin, origin);
        vm->set_field_vector(e, f().mins, mins);
        vm->set_field_vector(e, f().maxs, maxs);
        vm->set_field_vector(e, f().size, sub(maxs, mins));
        return e;
    }
    void move_to(uint32_t e, const Vec3f& origin, bool touch = false) {
        vm->set_field_vector(e, f().origin, origin);
        world->link(e, touch);
    }
    float count() const { return vm->global_float(touch_count); }
    uint32_t entity(uint32_t e) const { return vm->entity_value(e); }
};

Env& env_of(void* host) {
    return *static_cast<Env*>(host);
}

void remove_victim(vm::Vm& vm, void* host) {
    Env& env = env_of(host);
    env.world->unlink(env.victim);
    vm.set_field_float(env.victim, env.f().solid, qc::kSolidNot);
}

void nested_relink(vm::Vm& vm, void* host) {
    Env& env = env_of(host);
    const auto other = vm.edict_of(vm.global_word(env.layout.globals.other));
    if (!other) vm.fail("other is not an entity");
    env.move_to(*other, env.nested_target, true);
}

// A progs with every field and global the world uses, and three touch functions:
//   count_touch:  touch_count += 1; last_self = self; last_other = other;
//   remove_touch: remove_victim();
//   nested_touch: nested();
std::unique_ptr<Env> make_env(uint32_t max_edicts = 64) {
    auto env = std::make_unique<Env>();
    SynthProgs p;
    const auto fl = uint16_t(DefType::float_), vec = uint16_t(DefType::vector);
    const auto ent = uint16_t(DefType::entity), fn = uint16_t(DefType::function);
    FieldOffsets& f = env->layout.fields;
    f.modelindex = p.field("modelindex", fl);
    f.absmin = p.field("absmin", vec, 3);
    f.absmax = p.field("absmax", vec, 3);
    f.movetype = p.field("movetype", fl);
    f.solid = p.field("solid", fl);
    f.origin = p.field("origin", vec, 3);
    f.mins = p.field("mins", vec, 3);
    f.maxs = p.field("maxs", vec, 3);
    f.size = p.field("size", vec, 3);
    f.touch = p.field("touch", fn);
    f.flags = p.field("flags", fl);
    f.owner = p.field("owner", ent);
    GlobalOffsets& g = env->layout.globals;
    g.self = p.global_word(0);
    g.other = p.global_word(0);
    g.time = p.global(0);
    p.name_global("self", ent, uint16_t(g.self));
    p.name_global("other", ent, uint16_t(g.other));
    p.name_global("time", fl, uint16_t(g.time));
    env->touch_count = p.global(0);
    env->last_self = p.global_word(0);
    env->last_other = p.global_word(0);
    const uint16_t one = p.global(1);
    const uint16_t remove_fn = p.global_function(p.builtin("remove_victim", 1));
    const uint16_t nested_fn = p.global_function(p.builtin("nested", 2));
    const auto c = uint16_t(env->touch_count);

    env->count_touch = p.function("count_touch");
    p.op(vm::kOpAddF, c, one, c);
    p.op(vm::kOpStoreEnt, uint16_t(g.self), uint16_t(env->last_self));
    p.op(vm::kOpStoreEnt, uint16_t(g.other), uint16_t(env->last_other));
    p.op(vm::kOpDone);
    env->remove_touch = p.function("remove_touch");
    p.op(vm::kOpCall0, remove_fn);
    p.op(vm::kOpDone);
    env->nested_touch = p.function("nested_touch");
    p.op(vm::kOpCall0, nested_fn);
    p.op(vm::kOpDone);

    auto progs = vm::parse_progs(p.bytes(), "world_test.dat");
    if (!progs) throw std::runtime_error(progs.error().to_string());
    vm::VmLimits limits;
    limits.max_edicts = max_edicts;
    env->vm = std::make_unique<vm::Vm>(std::move(*progs), limits);
    env->vm->set_builtins(kBuiltins, env.get());
    env->vm->set_num_edicts(1);  // the world
    env->world = std::make_unique<World>(*env->vm, env->layout);
    return env;
}

// LibreQuake's own progs.dat, its layout found by name.
std::unique_ptr<Env> make_real_env() {
    auto bytes = read_file(test::lq1_dir() + "/progs.dat");
    if (!bytes) throw std::runtime_error(bytes.error().to_string());
    auto progs = vm::parse_progs(*bytes, "progs.dat");
    if (!progs) throw std::runtime_error(progs.error().to_string());
    auto layout = resolve_layout(*progs);
    if (!layout) throw std::runtime_error(layout.error().to_string());
    auto env = std::make_unique<Env>();
    env->layout = *layout;
    env->vm = std::make_unique<vm::Vm>(std::move(*progs));
    env->vm->set_num_edicts(1);
    env->world = std::make_unique<World>(*env->vm, env->layout);
    return env;
}

void expect_vec_eq(const Vec3f& a, const Vec3f& b, const char* what) {
    for (int i = 0; i < 3; ++i) EXPECT_FLOAT_EQ(a[i], b[i]) << what << " [" << i << "]";
}

// ---- linking ----

TEST(ServerWorld, LinkSetsAbsBoxInLibreQuakeProgs) {
    auto env = make_real_env();
    const auto bsp = load_map("start.bsp");
    env->world->set_level(bsp.get(), level_models(*bsp));
    const Vec3f origin{100, 200, 300};

    const uint32_t box = env->spawn(qc::kSolidSlideBox, origin, kPlayerMins, kPlayerMaxs);
    env->world->link(box, false);
    expect_vec_eq(env->vm->field_vector(box, env->f().absmin), {83, 183, 275}, "absmin");
    expect_vec_eq(env->vm->field_vector(box, env->f().absmax), {117, 217, 333}, "absmax");
    EXPECT_TRUE(env->world->linked(box));

    // Items grow by 15 sideways and not at all vertically.
    const uint32_t item = env->spawn(qc::kSolidTrigger, origin, {-16, -16, 0}, {16, 16, 56});
    env->vm->set_field_float(item, env->f().flags, qc::kFlItem | qc::kFlOnGround);
    env->world->link(item, false);
    expect_vec_eq(env->vm->field_vector(item, env->f().absmin), {69, 169, 300}, "item absmin");
    expect_vec_eq(env->vm->field_vector(item, env->f().absmax), {131, 231, 356}, "item absmax");

    // SOLID_NOT: the abs box is still set, but nothing is linked; the world is never linked.
    const uint32_t ghost = env->spawn(qc::kSolidNot, origin, {-1, -2, -3}, {4, 5, 6});
    env->world->link(ghost, false);
    expect_vec_eq(env->vm->field_vector(ghost, env->f().absmin), {98, 197, 296}, "ghost absmin");
    EXPECT_FALSE(env->world->linked(ghost));
    env->vm->set_field_float(0, env->f().solid, qc::kSolidBsp);
    env->world->link(0, false);
    EXPECT_FALSE(env->world->linked(0));

    env->world->unlink(box);
    EXPECT_FALSE(env->world->linked(box));
    env->world->link(box, false);
    env->world->clear();
    EXPECT_FALSE(env->world->linked(box));
}

TEST(ServerWorld, FreeEdictsAreNotLinked) {
    auto env = make_real_env();
    env->world->set_level(nullptr, {});
    EdictPool pool;
    pool.reset(*env->vm, 1);
    env->world->set_edict_pool(&pool);
    const auto e = pool.alloc(*env->vm, 0);
    ASSERT_TRUE(e);
    env->vm->set_field_float(*e, env->f().solid, qc::kSolidBbox);
    env->world->link(*e, false);
    EXPECT_TRUE(env->world->linked(*e));
    env->world->unlink(*e);
    pool.free(*env->vm, env->layout, *e, 0);
    env->vm->set_field_float(*e, env->f().solid, qc::kSolidBbox);  // QuakeC wrote to it anyway
    env->world->link(*e, false);
    EXPECT_FALSE(env->world->linked(*e));
}

// ---- traces against the world ----

TEST(ServerWorld, BoxTracedDownFromPlayerStartLandsOnFloor) {
    auto env = make_env();
    const auto bsp = load_map("start.bsp");
    env->world->set_level(bsp.get(), level_models(*bsp));
    // Player starts stand on the floor; drop from a little above it.
    const Vec3f spawn = player_start(*bsp);
    const Vec3f start = add(spawn, {0, 0, 20});
    ASSERT_EQ(point_contents(*bsp, 1, start), bsp_contents::empty);
    const Vec3f end = sub(start, {0, 0, 1000});

    const MoveTrace t =
        env->world->move(start, kPlayerMins, kPlayerMaxs, end, MoveKind::normal, kNoPassEdict);
    ASSERT_LT(t.fraction, 1);
    ASSERT_TRUE(t.entity);
    EXPECT_EQ(*t.entity, 0u);  // the world
    EXPECT_FALSE(t.start_solid);
    EXPECT_FALSE(t.all_solid);
    EXPECT_TRUE(t.in_open);
    EXPECT_FALSE(t.in_water);
    // A floor: the plane faces up, and the box stops DIST_EPSILON above the hull-1 plane.
    EXPECT_GT(t.plane_normal[2], 0.7f);
    const Vec3f& n = t.plane_normal;
    EXPECT_NEAR(n[0] * t.end_pos[0] + n[1] * t.end_pos[1] + n[2] * t.end_pos[2] - t.plane_dist,
                kDistEpsilon, 0.001f);
    // start.bsp's spawn rests on a flat floor: the box comes back to it, DIST_EPSILON above.
    EXPECT_NEAR(t.end_pos[2], spawn[2] + kDistEpsilon, 1e-3f);
    EXPECT_NEAR(t.fraction, (20 - kDistEpsilon) / 1000, 1e-6f);
    EXPECT_FLOAT_EQ(t.end_pos[0], start[0]);
    EXPECT_FLOAT_EQ(t.end_pos[1], start[1]);
    EXPECT_NE(point_contents(*bsp, 1, t.end_pos), bsp_contents::solid);
    EXPECT_EQ(point_contents(*bsp, 1, sub(t.end_pos, {0, 0, 1})), bsp_contents::solid);
    // The same sweep straight through hull 1.
    const BspTrace direct = trace_hull(*bsp, 1, start, end);
    EXPECT_EQ(t.fraction, direct.fraction);
    expect_vec_eq(t.end_pos, direct.end, "end");
    expect_vec_eq(t.plane_normal, direct.plane_normal, "normal");

    // Standing on the floor, a move down is blocked at once without being in solid.
    const MoveTrace standing =
        env->world->move(spawn, kPlayerMins, kPlayerMaxs, end, MoveKind::normal, kNoPassEdict);
    EXPECT_EQ(standing.fraction, 0);
    EXPECT_FALSE(standing.start_solid);
    expect_vec_eq(standing.end_pos, spawn, "standing end");
}

TEST(ServerWorld, RandomWorldTracesMatchHullOne) {
    auto env = make_env();
    const auto bsp = load_map("start.bsp");
    env->world->set_level(bsp.get(), level_models(*bsp));
    const BspModel& w = bsp->models[0];
    const Vec3f spawn = player_start(*bsp);
    std::mt19937 rng(1234);
    auto uniform = [&](float lo, float hi) {
        return std::uniform_real_distribution<float>(lo, hi)(rng);
    };
    int hits = 0, clear = 0, all_solid = 0;
    for (int i = 0; i < 2000; ++i) {
        Vec3f start, end;
        for (int k = 0; k < 3; ++k) {
            // Half start near the player start (open space), half anywhere in the map.
            start[k] = i % 2 ? uniform(w.mins[k], w.maxs[k]) : spawn[k] + uniform(-64, 64);
            const float reach = i % 4 < 2 ? 600 : 48;
            end[k] = start[k] + uniform(-reach, reach);
        }
        const MoveTrace t =
            env->world->move(start, kPlayerMins, kPlayerMaxs, end, MoveKind::normal, kNoPassEdict);
        const BspTrace d = trace_hull(*bsp, 1, start, end);
        SCOPED_TRACE(::testing::Message() << "trace " << i);
        EXPECT_EQ(t.all_solid, d.all_solid);
        EXPECT_EQ(t.start_solid, d.start_solid);
        if (d.all_solid) {
            // Quake reports a move that never leaves solid as fraction 1 ending at `end`.
            ++all_solid;
            EXPECT_EQ(t.fraction, 1);
            EXPECT_EQ(t.end_pos, end);
            EXPECT_FALSE(t.in_open || t.in_water);
            continue;
        }
        EXPECT_EQ(t.fraction, d.fraction);
        EXPECT_EQ(t.end_pos, d.end);
        EXPECT_EQ(t.plane_normal, d.plane_normal);
        EXPECT_EQ(t.plane_dist, d.plane_dist);
        EXPECT_EQ(t.entity.has_value(), d.hit() || d.start_solid);
        (d.hit() ? hits : clear)++;
    }
    // The sample covers every kind of result.
    EXPECT_GT(hits, 200);
    EXPECT_GT(clear, 100);
    EXPECT_GT(all_solid, 100);
}

// The first leaf of `bsp` with liquid whose box centre is in it, and an empty point above.
bool find_liquid(const Bsp& bsp, Vec3f& in_liquid, Vec3f& above) {
    for (uint32_t l = 1; l <= bsp.models[0].visleafs && l < bsp.leafs.size(); ++l) {
        const BspLeaf& leaf = bsp.leafs[l];
        if (leaf.contents > bsp_contents::water || leaf.contents < bsp_contents::lava) continue;
        const Vec3f c{(leaf.mins[0] + leaf.maxs[0]) / 2, (leaf.mins[1] + leaf.maxs[1]) / 2,
                      (leaf.mins[2] + leaf.maxs[2]) / 2};
        if (point_contents(bsp, 0, c) != leaf.contents) continue;
        for (float dz = 4; dz < 512; dz += 4) {
            const Vec3f p{c[0], c[1], c[2] + dz};
            const int32_t contents = point_contents(bsp, 0, p);
            if (contents == bsp_contents::solid) break;
            if (contents == bsp_contents::empty) {
                in_liquid = c;
                above = p;
                return true;
            }
        }
    }
    return false;
}

TEST(ServerWorld, TracesReportOpenAndLiquidTheyCross) {
    auto env = make_env();
    bool found = false;
    for (const char* name : {"start.bsp", "e2m3.bsp", "lq1m1.bsp"}) {
        const auto bsp = load_map(name);
        Vec3f liquid, air;
        if (!find_liquid(*bsp, liquid, air)) continue;
        found = true;
        SCOPED_TRACE(name);
        env->world->set_level(bsp.get(), level_models(*bsp));
        EXPECT_EQ(env->world->point_contents(air), bsp_contents::empty);
        EXPECT_LE(env->world->point_contents(liquid), bsp_contents::water);

        // Down through the surface: both (monsters cannot see across it, ai.qc's visible()).
        MoveTrace t = env->world->move(air, kZero, kZero, liquid, MoveKind::no_monsters, 0);
        EXPECT_EQ(t.fraction, 1);
        EXPECT_TRUE(t.in_open);
        EXPECT_TRUE(t.in_water);
        t = env->world->move(liquid, kZero, kZero, liquid, MoveKind::no_monsters, 0);
        EXPECT_FALSE(t.in_open);
        EXPECT_TRUE(t.in_water);
        t = env->world->move(air, kZero, kZero, air, MoveKind::no_monsters, 0);
        EXPECT_TRUE(t.in_open);
        EXPECT_FALSE(t.in_water);
        break;
    }
    EXPECT_TRUE(found) << "no map with reachable liquid";
}

TEST(ServerWorld, PointContentsAndEntityPosition) {
    auto env = make_env();
    EXPECT_EQ(env->world->point_contents({0, 0, 0}), bsp_contents::empty);  // no level yet
    const auto bsp = load_map("start.bsp");
    env->world->set_level(bsp.get(), level_models(*bsp));
    const Vec3f start = player_start(*bsp);
    EXPECT_EQ(env->world->point_contents(start), bsp_contents::empty);
    EXPECT_EQ(env->world->point_contents({1e5f, 1e5f, 1e5f}), bsp_contents::solid);

    const uint32_t player = env->spawn(qc::kSolidSlideBox, start, kPlayerMins, kPlayerMaxs);
    env->world->link(player, false);
    EXPECT_FALSE(env->world->test_entity_position(player));  // it skips itself
    const uint32_t crate =
        env->spawn(qc::kSolidBbox, add(start, {20, 0, 0}), {-8, -8, -8}, {8, 8, 8});
    env->world->link(crate, false);
    EXPECT_EQ(env->world->test_entity_position(player), crate);
    env->world->unlink(crate);
    env->move_to(player, sub(start, {0, 0, 40}));  // sunk into the floor
    EXPECT_EQ(env->world->test_entity_position(player), 0u);
}

// ---- traces against entities (no map: only the entities themselves) ----

struct EntityScene {
    std::unique_ptr<Env> env = make_env();
    uint32_t near = 0, far = 0;
    EntityScene() {
        env->world->set_level(nullptr, {});
        near = env->spawn(qc::kSolidBbox, {100, 0, 0}, {-8, -8, -8}, {8, 8, 8});
        far = env->spawn(qc::kSolidSlideBox, {200, 0, 0}, {-8, -8, -8}, {8, 8, 8});
        env->world->link(far, false);  // linked first: order must not matter
        env->world->link(near, false);
    }
    MoveTrace line(uint32_t pass, MoveKind kind = MoveKind::normal, const Vec3f& mins = kZero,
                   const Vec3f& maxs = kZero) {
        return env->world->move({0, 0, 0}, mins, maxs, {300, 0, 0}, kind, pass);
    }
};

TEST(ServerWorld, TraceHitsTheNearerEntity) {
    EntityScene s;
    MoveTrace t = s.line(kNoPassEdict);
    ASSERT_TRUE(t.entity);
    EXPECT_EQ(*t.entity, s.near);
    // The box face is at x = 92; the trace stops DIST_EPSILON short of it.
    EXPECT_FLOAT_EQ(t.fraction, (92 - kDistEpsilon) / 300);
    EXPECT_NEAR(t.end_pos[0], 92 - kDistEpsilon, 1e-4f);
    expect_vec_eq(t.plane_normal, {-1, 0, 0}, "normal");
    EXPECT_FALSE(t.start_solid);
    EXPECT_TRUE(t.in_open);

    // A moving box meets it earlier by its own half width (Minkowski sum).
    t = s.line(kNoPassEdict, MoveKind::normal, {-4, -4, -4}, {4, 4, 4});
    EXPECT_EQ(t.entity, s.near);
    EXPECT_NEAR(t.end_pos[0], 88 - kDistEpsilon, 1e-4f);
    // Just missing its side: |y| = 8 + 4 + 1 passes by.
    t = s.env->world->move({0, 13, 0}, {-4, -4, -4}, {4, 4, 4}, {300, 13, 0}, MoveKind::normal,
                           kNoPassEdict);
    EXPECT_EQ(t.fraction, 1);
    EXPECT_FALSE(t.entity);
}

TEST(ServerWorld, PassedictItsMissilesAndItsOwnerAreSkipped) {
    EntityScene s;
    EXPECT_EQ(s.line(s.near).entity, s.far);  // the mover itself
    Env& env = *s.env;
    const uint32_t shooter = env.spawn(qc::kSolidSlideBox, {-500, 0, 0}, kPlayerMins, kPlayerMaxs);
    env.world->link(shooter, false);
    env.vm->set_field_int(s.near, env.f().owner, int32_t(env.entity(shooter)));
    EXPECT_EQ(s.line(shooter).entity, s.far);  // its own missile
    EXPECT_EQ(s.line(kNoPassEdict).entity, s.near);
    env.vm->set_field_int(shooter, env.f().owner, int32_t(env.entity(s.far)));
    const MoveTrace t = s.line(shooter);  // and its owner
    EXPECT_FALSE(t.entity);
    EXPECT_EQ(t.fraction, 1);
    expect_vec_eq(t.end_pos, {300, 0, 0}, "end");
    // A passedict past the edicts is no passedict.
    EXPECT_EQ(s.line(1u << 30).entity, s.near);
    // The world as passedict (QuakeC's traceline(..., world)) owns every entity whose owner is
    // the world, and Quake skips those: `far` has no owner; `near` is still the shooter's.
    env.vm->set_field_int(s.near, env.f().owner, 0);
    EXPECT_FALSE(s.line(0).entity);
    env.vm->set_field_int(s.far, env.f().owner, int32_t(env.entity(shooter)));
    EXPECT_EQ(s.line(0).entity, s.far);
}

TEST(ServerWorld, NoMonstersIgnoresBoxesAndMissilesGrowAgainstMonsters) {
    EntityScene s;
    MoveTrace t = s.line(kNoPassEdict, MoveKind::no_monsters);
    EXPECT_FALSE(t.entity);
    EXPECT_EQ(t.fraction, 1);

    Env& env = *s.env;
    const uint32_t monster = env.spawn(qc::kSolidSlideBox, {50, 20, 0}, {-8, -8, -8}, {8, 8, 8});
    env.vm->set_field_float(monster, env.f().flags, qc::kFlMonster);
    env.world->link(monster, false);
    EXPECT_EQ(s.line(kNoPassEdict).entity, s.near);  // a point passes 12 units beside it
    t = s.line(kNoPassEdict, MoveKind::missile);     // a missile is 15 units each way to it
    EXPECT_EQ(t.entity, monster);
    EXPECT_NEAR(t.end_pos[0], 50 - 8 - 15 - kDistEpsilon, 1e-4f);
    // Missiles stay points against what is not a monster.
    env.world->unlink(monster);
    t = s.line(kNoPassEdict, MoveKind::missile);
    EXPECT_EQ(t.entity, s.near);
    EXPECT_NEAR(t.end_pos[0], 92 - kDistEpsilon, 1e-4f);
}

TEST(ServerWorld, StartingInsideABoxIsStartSolid) {
    EntityScene s;
    World& world = *s.env->world;
    // Out of it and on. Quake lets a start-solid result replace whatever was found before it,
    // and a later nearer hit replace that but keep start_solid: the area list's order shows.
    MoveTrace t =
        world.move({100, 0, 0}, kZero, kZero, {300, 0, 0}, MoveKind::normal, kNoPassEdict);
    EXPECT_TRUE(t.start_solid);
    EXPECT_FALSE(t.all_solid);
    EXPECT_EQ(t.entity, s.near);  // tested after `far`, whose hit it replaced
    EXPECT_EQ(t.fraction, 1);
    world.link(s.far, false);  // now last in the list
    t = world.move({100, 0, 0}, kZero, kZero, {300, 0, 0}, MoveKind::normal, kNoPassEdict);
    EXPECT_TRUE(t.start_solid);
    EXPECT_FALSE(t.all_solid);
    EXPECT_EQ(t.entity, s.far);
    EXPECT_NEAR(t.end_pos[0], 192 - kDistEpsilon, 1e-4f);
    // Wholly inside: all solid, Quake's fraction 1 and the requested end.
    t = world.move({100, 0, 0}, kZero, kZero, {104, 0, 0}, MoveKind::normal, kNoPassEdict);
    EXPECT_TRUE(t.start_solid);
    EXPECT_TRUE(t.all_solid);
    EXPECT_EQ(t.fraction, 1);
    expect_vec_eq(t.end_pos, {104, 0, 0}, "end");
    EXPECT_EQ(t.entity, s.near);
    EXPECT_FALSE(t.in_open);
    // On a max face is outside, on a min face inside (the six-plane box hull's rule).
    EXPECT_FALSE(world.move({108, 0, 0}, kZero, kZero, {108, 0, 0}, MoveKind::normal, kNoPassEdict)
                     .start_solid);
    EXPECT_TRUE(world.move({92, 0, 0}, kZero, kZero, {92, 0, 0}, MoveKind::normal, kNoPassEdict)
                    .start_solid);
}

// ---- brush entities ----

TEST(ServerWorld, DoorSubmodelBlocksWhereItsOriginPutsIt) {
    auto env = make_env();
    const auto bsp = load_map("start.bsp");
    ASSERT_GE(bsp->models.size(), 2u);
    env->world->set_level(bsp.get(), level_models(*bsp));
    const BspModel& m = bsp->models[1];
    const Vec3f centre{(m.mins[0] + m.maxs[0]) / 2, (m.mins[1] + m.maxs[1]) / 2,
                       (m.mins[2] + m.maxs[2]) / 2};
    // Across its thinner horizontal side, through the middle.
    const int axis = m.maxs[0] - m.mins[0] < m.maxs[1] - m.mins[1] ? 0 : 1;
    Vec3f start = centre, end = centre;
    const float reach = (m.maxs[axis] - m.mins[axis]) / 2 + 16;
    start[axis] -= reach;
    end[axis] += reach;
    const BspTrace world_only = trace_hull(*bsp, 0, start, end);
    ASSERT_FALSE(world_only.hit() || world_only.start_solid) << "the doorway is not open";

    const uint32_t door = env->spawn(qc::kSolidBsp, kZero, m.mins, m.maxs);
    env->vm->set_field_float(door, env->f().modelindex, 2);  // "*1"
    env->vm->set_field_float(door, env->f().movetype, qc::kMovePush);
    env->world->link(door, false);
    MoveTrace t = env->world->move(start, kZero, kZero, end, MoveKind::no_monsters, kNoPassEdict);
    EXPECT_EQ(t.entity, door);  // SOLID_BSP blocks even MOVE_NOMONSTERS
    const BspTrace direct = trace_hull(*bsp, 0, start, end, 1);
    ASSERT_TRUE(direct.hit());
    EXPECT_EQ(t.fraction, direct.fraction);
    expect_vec_eq(t.end_pos, direct.end, "end");

    // Opened upwards by its height: the doorway is clear again.
    const Vec3f lift{0, 0, m.maxs[2] - m.mins[2] + 8};
    env->move_to(door, lift);
    t = env->world->move(start, kZero, kZero, end, MoveKind::normal, kNoPassEdict);
    EXPECT_NE(t.entity, std::optional<uint32_t>(door));
    EXPECT_EQ(t.fraction, world_only.fraction);
}

TEST(ServerWorld, BrushHullFollowsBoxWidthAndOffset) {
    auto env = make_env();
    const auto bsp = load_map("start.bsp");
    env->world->set_level(nullptr, {});  // the door alone, its model precached later
    env->world->set_model(2, {bsp.get(), 1});
    const BspModel& m = bsp->models[1];
    const Vec3f origin{1000, -500, 64};
    const uint32_t door = env->spawn(qc::kSolidBsp, origin, m.mins, m.maxs);
    env->vm->set_field_float(door, env->f().modelindex, 2);
    env->world->link(door, false);
    const Vec3f centre = add(origin, {(m.mins[0] + m.maxs[0]) / 2, (m.mins[1] + m.maxs[1]) / 2,
                                      (m.mins[2] + m.maxs[2]) / 2});
    const Vec3f start = sub(centre, {200, 150, 0}), end = add(centre, {200, 150, 0});

    struct Case {
        Vec3f mins, maxs;
        int hull;
    };
    const Case cases[] = {
        {{0, 0, 0}, {0, 0, 0}, 0},          {{-1, -1, -1}, {1, 1, 1}, 0},
        {kPlayerMins, kPlayerMaxs, 1},      {{-16, -16, 0}, {16, 16, 56}, 1},
        {{-32, -32, -24}, {32, 32, 64}, 2}, {{-20, -20, -10}, {20, 20, 10}, 2},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(::testing::Message()
                     << "hull " << c.hull << " width " << c.maxs[0] - c.mins[0]);
        // The hull's box stands for the moving box: shift the model by the difference of mins.
        const Vec3f offset = add(sub(bsp->hulls[c.hull].clip_mins, c.mins), origin);
        const BspTrace d = trace_hull(*bsp, c.hull, sub(start, offset), sub(end, offset), 1);
        ASSERT_TRUE(d.hit());
        const MoveTrace t =
            env->world->move(start, c.mins, c.maxs, end, MoveKind::normal, kNoPassEdict);
        EXPECT_EQ(t.entity, door);
        EXPECT_EQ(t.fraction, d.fraction);
        expect_vec_eq(t.end_pos, add(d.end, offset), "end");
        expect_vec_eq(t.plane_normal, d.plane_normal, "normal");
    }
    // Without a brush model (modelindex of an alias model) SOLID_BSP is the entity's box.
    env->vm->set_field_float(door, env->f().modelindex, 0);
    const MoveTrace t = env->world->move(start, kZero, kZero, end, MoveKind::normal, kNoPassEdict);
    EXPECT_EQ(t.entity, door);
    EXPECT_LT(t.fraction, 1);
}

// ---- triggers ----

TEST(ServerWorld, OverlappingTriggerIsTouchedOnce) {
    auto env = make_env();
    World& world = *env->world;
    world.set_level(nullptr, {});
    const uint32_t near = env->spawn(qc::kSolidTrigger, {0, 0, 0}, {-32, -32, -32}, {32, 32, 32});
    const uint32_t far = env->spawn(qc::kSolidTrigger, {500, 0, 0}, {-32, -32, -32}, {32, 32, 32});
    const uint32_t inert = env->spawn(qc::kSolidTrigger, {0, 0, 0}, {-32, -32, -32}, {32, 32, 32});
    for (uint32_t e : {near, far}) env->vm->set_field_int(e, env->f().touch, env->count_touch);
    for (uint32_t e : {near, far, inert}) world.link(e, false);
    const uint32_t player = env->spawn(qc::kSolidSlideBox, {40, 0, 0}, kPlayerMins, kPlayerMaxs);
    env->vm->set_global_word(env->layout.globals.self, 12345);
    env->vm->set_global_word(env->layout.globals.other, 678);

    world.link(player, true);
    ASSERT_FALSE(env->vm->error()) << env->vm->error()->to_string();
    EXPECT_EQ(env->count(), 1);
    EXPECT_EQ(env->vm->global_word(env->last_self), env->entity(near));
    EXPECT_EQ(env->vm->global_word(env->last_other), env->entity(player));
    EXPECT_EQ(env->vm->global_word(env->layout.globals.self), 12345u);  // restored
    EXPECT_EQ(env->vm->global_word(env->layout.globals.other), 678u);

    world.link(player, false);  // no touches asked for
    EXPECT_EQ(env->count(), 1);
    env->move_to(player, {1000, 0, 0}, true);  // touches nothing there
    EXPECT_EQ(env->count(), 1);
    env->move_to(player, {500, 0, 60}, true);  // abs boxes apart: 60 - 24 - 1 = 35 > 32 + 1
    EXPECT_EQ(env->count(), 1);
    env->move_to(player, {500, 0, 58}, true);  // 58 - 25 = 33: boxes that meet count
    EXPECT_EQ(env->count(), 2);
    EXPECT_EQ(env->vm->global_word(env->last_self), env->entity(far));

    // SOLID_NOT entities are not linked and touch nothing.
    env->vm->set_field_float(player, env->f().solid, qc::kSolidNot);
    env->move_to(player, {0, 0, 0}, true);
    EXPECT_EQ(env->count(), 2);
}

TEST(ServerWorld, TriggersAreCheckedAgainJustBeforeTheirTouch) {
    auto env = make_env();
    World& world = *env->world;
    world.set_level(nullptr, {});
    const Vec3f box_min{-32, -32, -32}, box_max{32, 32, 32};
    const uint32_t remover = env->spawn(qc::kSolidTrigger, kZero, box_min, box_max);
    const uint32_t counter = env->spawn(qc::kSolidTrigger, kZero, box_min, box_max);
    env->vm->set_field_int(remover, env->f().touch, env->remove_touch);
    env->vm->set_field_int(counter, env->f().touch, env->count_touch);
    world.link(remover, false);  // first in the list
    world.link(counter, false);
    const uint32_t player = env->spawn(qc::kSolidSlideBox, kZero, kPlayerMins, kPlayerMaxs);

    env->victim = player + 1;  // an edict that does not matter: both touch
    world.link(player, true);
    EXPECT_EQ(env->count(), 1);
    env->victim = counter;  // the first touch removes the second trigger
    world.link(player, true);
    ASSERT_FALSE(env->vm->error()) << env->vm->error()->to_string();
    EXPECT_EQ(env->count(), 1);
    EXPECT_FALSE(world.linked(counter));
}

TEST(ServerWorld, TouchFunctionsMayRelinkWithTouches) {
    auto env = make_env();
    World& world = *env->world;
    world.set_level(nullptr, {});
    const Vec3f box_min{-32, -32, -32}, box_max{32, 32, 32};
    const uint32_t mover = env->spawn(qc::kSolidTrigger, kZero, box_min, box_max);
    const uint32_t left_behind = env->spawn(qc::kSolidTrigger, kZero, box_min, box_max);
    const uint32_t there = env->spawn(qc::kSolidTrigger, {1000, 0, 0}, box_min, box_max);
    env->vm->set_field_int(mover, env->f().touch, env->nested_touch);
    for (uint32_t e : {left_behind, there}) {
        env->vm->set_field_int(e, env->f().touch, env->count_touch);
    }
    for (uint32_t e : {mover, left_behind, there}) world.link(e, false);
    const uint32_t player = env->spawn(qc::kSolidSlideBox, kZero, kPlayerMins, kPlayerMaxs);
    env->nested_target = {1000, 0, 0};

    world.link(player, true);
    ASSERT_FALSE(env->vm->error()) << env->vm->error()->to_string();
    // The nested link touched `there`; the player had left `left_behind` before its turn.
    EXPECT_EQ(env->count(), 1);
    EXPECT_EQ(env->vm->global_word(env->last_self), env->entity(there));
    expect_vec_eq(env->vm->field_vector(player, env->f().origin), {1000, 0, 0}, "origin");
}

// ---- PVS leafs ----

TEST(ServerWorld, LeafsOfHoldTheLeafsUnderTheBox) {
    auto env = make_env();
    const auto bsp = load_map("start.bsp");
    env->world->set_level(bsp.get(), level_models(*bsp));
    const Vec3f start = player_start(*bsp);
    const uint32_t player = env->spawn(qc::kSolidSlideBox, start, kPlayerMins, kPlayerMaxs);
    env->vm->set_field_float(player, env->f().modelindex, 3);
    env->world->link(player, false);

    const std::span<const int32_t> leafs = env->world->leafs_of(player);
    ASSERT_FALSE(leafs.empty());
    EXPECT_TRUE(env->world->leafs_complete(player));
    auto listed = [&](uint32_t leaf) {
        return std::find(leafs.begin(), leafs.end(), int32_t(leaf)) != leafs.end();
    };
    EXPECT_TRUE(listed(leaf_at(*bsp, start)));
    // Every corner of the abs box that is not in solid lies in a listed leaf.
    const Vec3f lo = env->vm->field_vector(player, env->f().absmin);
    const Vec3f hi = env->vm->field_vector(player, env->f().absmax);
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3f p{corner & 1 ? hi[0] : lo[0], corner & 2 ? hi[1] : lo[1],
                      corner & 4 ? hi[2] : lo[2]};
        const uint32_t leaf = leaf_at(*bsp, p);
        if (bsp->leafs[leaf].contents != bsp_contents::solid) {
            EXPECT_TRUE(listed(leaf)) << corner;
        }
    }
    for (int32_t leaf : leafs) {
        ASSERT_GT(leaf, 0);
        ASSERT_LT(size_t(leaf), bsp->leafs.size());
        EXPECT_NE(bsp->leafs[size_t(leaf)].contents, bsp_contents::solid);
        EXPECT_EQ(std::count(leafs.begin(), leafs.end(), leaf), 1);
    }

    // No model: no leafs (Quake only looks for entities that can be seen).
    const uint32_t bare = env->spawn(qc::kSolidTrigger, start, kPlayerMins, kPlayerMaxs);
    env->world->link(bare, false);
    EXPECT_TRUE(env->world->leafs_of(bare).empty());
}

TEST(ServerWorld, LeafListStopsAtThirtyTwo) {
    auto env = make_env();
    const auto bsp = load_map("e2m3.bsp");
    env->world->set_level(bsp.get(), level_models(*bsp));
    size_t open_leafs = 0;
    for (uint32_t l = 1; l <= bsp->models[0].visleafs; ++l) {
        open_leafs += bsp->leafs[l].contents != bsp_contents::solid;
    }
    ASSERT_GT(open_leafs, World::kMaxEntityLeafs);
    const BspModel& w = bsp->models[0];
    const uint32_t huge = env->spawn(qc::kSolidNot, kZero, w.mins, w.maxs);
    env->vm->set_field_float(huge, env->f().modelindex, 1);
    env->world->link(huge, false);
    EXPECT_EQ(env->world->leafs_of(huge).size(), World::kMaxEntityLeafs);
    EXPECT_FALSE(env->world->leafs_complete(huge));
}

// ---- robustness and allocation ----

TEST(ServerWorld, BadEdictNumbersAreIgnored) {
    auto env = make_env();
    const auto bsp = load_map("start.bsp");
    env->world->set_level(bsp.get(), level_models(*bsp));
    for (uint32_t bad : {64u, 65u, 1u << 20, UINT32_MAX}) {
        env->world->link(bad, true);
        env->world->unlink(bad);
        EXPECT_FALSE(env->world->linked(bad));
        EXPECT_TRUE(env->world->leafs_of(bad).empty());
        EXPECT_FALSE(env->world->test_entity_position(bad));
    }
    // Garbage in fields: NaN solid, huge modelindex, NaN origin.
    const uint32_t e = env->spawn(qc::kSolidBsp, {NAN, 0, 0}, kPlayerMins, kPlayerMaxs);
    env->vm->set_field_float(e, env->f().modelindex, 1e30f);
    env->world->link(e, true);
    env->vm->set_field_float(e, env->f().solid, NAN);
    env->world->link(e, true);
    env->vm->set_field_float(e, env->f().solid, qc::kSolidBsp);
    env->vm->set_field_float(e, env->f().modelindex, -7);
    env->world->link(e, true);
    const MoveTrace t = env->world->move(player_start(*bsp), kZero, kZero, {NAN, 0, 0},
                                         MoveKind::normal, kNoPassEdict);
    EXPECT_TRUE(t.all_solid);  // trace_hull refuses non-finite points
}

TEST(ServerWorld, LinkingTracingAndTouchingDoNotAllocate) {
    auto env = make_env();
    const auto bsp = load_map("start.bsp");
    env->world->set_level(bsp.get(), level_models(*bsp));
    const Vec3f start = player_start(*bsp);
    const uint32_t trigger = env->spawn(qc::kSolidTrigger, start, {-64, -64, -64}, {64, 64, 64});
    env->vm->set_field_int(trigger, env->f().touch, env->count_touch);
    env->world->link(trigger, false);
    const uint32_t player = env->spawn(qc::kSolidSlideBox, start, kPlayerMins, kPlayerMaxs);
    env->vm->set_field_float(player, env->f().modelindex, 3);
    const uint32_t crate =
        env->spawn(qc::kSolidBbox, add(start, {64, 0, 0}), {-8, -8, -8}, {8, 8, 8});
    env->world->link(crate, false);

    auto frame = [&](int i) {
        env->move_to(player, add(start, {float(i % 7), 0, 0}), true);
        env->world->move(start, kPlayerMins, kPlayerMaxs, add(start, {200, float(i), -100}),
                         MoveKind::normal, player);
        env->world->move(start, kZero, kZero, add(start, {0, 300, float(i)}), MoveKind::missile,
                         player);
        env->world->test_entity_position(player);
    };
    frame(0);
    const long before = ::nq::test::g_allocations.load();
    for (int i = 1; i < 200; ++i) frame(i);
    EXPECT_EQ(::nq::test::g_allocations.load() - before, 0);
    EXPECT_EQ(env->count(), 200);
}

}  // namespace
}  // namespace nq::server

// Server physics (physics.h, player_move.h) on LibreQuake's start.bsp, checked against values
// computed here from Quake's rules: free fall integrated frame by frame, the ground
// friction/acceleration recurrence, the 18-unit step, pushers shoving and being blocked, think
// functions running within their frame. start.bsp is two flat rooms (floor z -248, x -511..-10
// and 10..511, y 1..639) divided by a wall with teleporters; the player starts at -192 288 -224.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "server/monster_move.h"
#include "server/player_move.h"
#include "server_physics_fixture.h"

namespace nq::server::test {
namespace {

constexpr float kFloor = -248;         // start.bsp's floor
constexpr float kPlayerStandZ = -224;  // a player's origin standing on it
const Vec3f kPlayerStart = {-192, 288, -224};

// A MOVETYPE_TOSS/BOUNCE point entity in the main room.
uint32_t spawn_tossed(PhysicsLevel& level, int movetype, const Vec3f& origin,
                      const Vec3f& velocity) {
    const uint32_t e = level.spawn_box(origin, {0, 0, 0}, {0, 0, 0}, movetype, qc::kSolidBbox);
    level.vm().set_field_vector(e, level.f().velocity, velocity);
    return e;
}

TEST(ServerPhysics, TossFallsWithQuakesIntegration) {
    PhysicsLevel level("start.bsp");
    const Vec3f start = {-300, 300, -40};
    const uint32_t e = spawn_tossed(level, qc::kMoveToss, start, {30, -20, 100});
    // Quake: gravity first, then the move with the new velocity, every frame.
    Vec3f pos = start, vel = {30, -20, 100};
    const float dt = PhysicsLevel::kFrame;
    for (int frame = 0; frame < 36; ++frame) {
        ASSERT_TRUE(level.frame());
        vel[2] -= 800.0f * dt;
        for (int i = 0; i < 3; ++i) pos[i] += vel[i] * dt;
        for (int i = 0; i < 3; ++i) {
            ASSERT_NEAR(level.origin(e)[i], pos[i], 1e-3) << "frame " << frame << " axis " << i;
        }
        ASSERT_NEAR(level.velocity(e)[2], vel[2], 1e-3);
    }
    EXPECT_GT(pos[2], kFloor + 10);  // still in the air: the expectation was a free fall
    EXPECT_FALSE(level.flags(e) & qc::kFlOnGround);
}

TEST(ServerPhysics, GravityFieldScalesTheFall) {
    PhysicsLevel level("start.bsp");
    ASSERT_NE(level.layout.field_gravity, 0u);
    const uint32_t e = spawn_tossed(level, qc::kMoveToss, {-300, 300, -40}, {0, 0, 0});
    level.vm().set_field_float(e, level.layout.field_gravity, 0.25f);
    ASSERT_TRUE(level.frame());
    EXPECT_NEAR(level.velocity(e)[2], -0.25f * 800 * PhysicsLevel::kFrame, 1e-4);
}

TEST(ServerPhysics, FlyingMissilesIgnoreGravity) {
    PhysicsLevel level("start.bsp");
    const uint32_t e = spawn_tossed(level, qc::kMoveFlyMissile, {-300, 300, -100}, {100, 0, 0});
    for (int i = 0; i < 10; ++i) ASSERT_TRUE(level.frame());
    EXPECT_FLOAT_EQ(level.velocity(e)[2], 0);
    EXPECT_NEAR(level.origin(e)[0], -300 + 100 * 10 * PhysicsLevel::kFrame, 1e-3);
    EXPECT_FLOAT_EQ(level.origin(e)[2], -100);
}

TEST(ServerPhysics, BouncingGrenadeComesToRestOnTheFloor) {
    PhysicsLevel level("start.bsp");
    const uint32_t e = spawn_tossed(level, qc::kMoveBounce, {-300, 300, -150}, {80, 40, 250});
    float top = -150;
    int bounces = 0;
    float last_vz = 250;
    for (int frame = 0; frame < 72 * 8 && !(level.flags(e) & qc::kFlOnGround); ++frame) {
        ASSERT_TRUE(level.frame());
        top = std::max(top, level.origin(e)[2]);
        const float vz = level.velocity(e)[2];
        if (last_vz < 0 && vz > 0) ++bounces;  // 1.5 overbounce: the floor sends it back up
        last_vz = vz;
    }
    ASSERT_TRUE(level.flags(e) & qc::kFlOnGround);
    EXPECT_GE(bounces, 1);
    EXPECT_GT(top, -150 + 30);
    EXPECT_NEAR(level.origin(e)[2], kFloor, 0.1);
    EXPECT_EQ(level.velocity(e), (Vec3f{0, 0, 0}));
    EXPECT_EQ(level.vm().field_int(e, level.f().groundentity), 0);  // the world
    // At rest it stays put.
    const Vec3f rest = level.origin(e);
    for (int frame = 0; frame < 36; ++frame) ASSERT_TRUE(level.frame());
    EXPECT_EQ(level.origin(e), rest);
    EXPECT_FALSE(level.world.test_entity_position(e));
    EXPECT_TRUE(level.sounds.sounds.empty());  // no water here
}

TEST(ServerPhysics, ThinkRunsWhenNextthinkFallsWithinTheFrame) {
    PhysicsLevel level("start.bsp");
    level.game.frame_time = 0.1f;
    const uint32_t e = level.spawn_box({-300, 300, -200}, {}, {}, qc::kMoveNone, qc::kSolidNot);
    level.vm().set_field_int(e, level.f().think, level.function("count_think"));
    // Not yet: after the end of this frame (time 1 .. 1.1).
    level.vm().set_field_float(e, level.f().nextthink, 1.15f);
    ASSERT_TRUE(level.frame());
    EXPECT_EQ(level.global("think_calls"), 0);
    // The next frame (1.1 .. 1.2) holds it: time is the think's own time.
    ASSERT_TRUE(level.frame());
    EXPECT_EQ(level.global("think_calls"), 1);
    EXPECT_FLOAT_EQ(level.global("think_time"), 1.15f);
    EXPECT_EQ(level.global_edict("think_self"), e);
    EXPECT_EQ(level.vm().field_float(e, level.f().nextthink), 0);
    // A think in the past runs at the frame's time, never earlier.
    level.vm().set_field_float(e, level.f().nextthink, 0.5f);
    ASSERT_TRUE(level.frame());
    EXPECT_EQ(level.global("think_calls"), 2);
    EXPECT_FLOAT_EQ(level.global("think_time"), float(level.game.time - 0.1));
    // nextthink 0 never thinks.
    ASSERT_TRUE(level.frame());
    EXPECT_EQ(level.global("think_calls"), 2);
}

TEST(ServerPhysics, StartFrameAndPlayerThinksRunForSpawnedClientsOnly) {
    PhysicsLevel level("start.bsp");
    level.place_player(kPlayerStart);
    ASSERT_TRUE(level.frame());
    EXPECT_EQ(level.global("start_frames"), 1);
    EXPECT_EQ(level.global("pre_thinks"), 0);
    level.player_spawned = 1;
    ASSERT_TRUE(level.frame());
    ASSERT_TRUE(level.frame());
    EXPECT_EQ(level.global("start_frames"), 3);
    EXPECT_EQ(level.global("pre_thinks"), 2);
    EXPECT_EQ(level.global("post_thinks"), 2);
    EXPECT_FLOAT_EQ(level.vm().global_float(level.layout.globals.frametime), PhysicsLevel::kFrame);
}

TEST(ServerPhysics, ForceRetouchCountsDownOncePerFrame) {
    PhysicsLevel level("start.bsp");
    level.vm().set_global_float(level.layout.globals.force_retouch, 2);
    ASSERT_TRUE(level.frame());
    EXPECT_EQ(level.vm().global_float(level.layout.globals.force_retouch), 1);
    ASSERT_TRUE(level.frame());
    ASSERT_TRUE(level.frame());
    EXPECT_EQ(level.vm().global_float(level.layout.globals.force_retouch), 0);
}

TEST(ServerPhysics, StuckPlayerGoesBackToItsLastGoodOrigin) {
    PhysicsLevel level("start.bsp");
    level.player_spawned = 1;
    level.place_player(kPlayerStart);
    ASSERT_TRUE(level.frame());  // remembers the good origin
    EXPECT_EQ(level.vm().field_vector(1, level.f().oldorigin), kPlayerStart);
    level.vm().set_field_vector(1, level.f().origin, {-192, 288, -236});  // 12 into the floor
    level.world.link(1, false);
    ASSERT_TRUE(level.world.test_entity_position(1));
    ASSERT_TRUE(level.frame());
    EXPECT_FALSE(level.world.test_entity_position(1));
    EXPECT_NEAR(level.origin(1)[2], kPlayerStandZ, 0.5);
    EXPECT_NE(level.host.debug.find("Unstuck."), std::string::npos);
}

TEST(ServerPhysics, QuakeCErrorStopsTheFrame) {
    PhysicsLevel level("start.bsp");
    const uint32_t e = level.spawn_box({-300, 300, -200}, {}, {}, qc::kMoveNone, qc::kSolidNot);
    level.vm().set_field_float(e, level.f().nextthink, 1.0f);  // think is 0: a null function
    EXPECT_FALSE(level.frame());
    ASSERT_TRUE(level.vm().error());
}

TEST(ServerPhysics, NanVelocityBecomesZeroAndSpeedIsCapped) {
    PhysicsLevel level("start.bsp");
    const uint32_t e =
        spawn_tossed(level, qc::kMoveFly, {-300, 300, -100}, {std::nanf(""), 5000, 0});
    level.vm().set_field_int(e, level.f().classname, level.vm().strings().make_level("rocket"));
    ASSERT_TRUE(level.frame());
    EXPECT_EQ(level.velocity(e)[0], 0);
    EXPECT_EQ(level.velocity(e)[1], 2000);
    EXPECT_NE(level.host.printed.find("NaN velocity on rocket"), std::string::npos)
        << level.host.printed;
}

TEST(ServerPhysics, TouchFunctionsOfBothRunOnImpact) {
    PhysicsLevel level("start.bsp");
    const uint32_t target = level.spawn_box({-200, 300, -232}, {-16, -16, -16}, {16, 16, 16},
                                            qc::kMoveNone, qc::kSolidBbox);
    level.vm().set_field_float(target, level.f().flags, qc::kFlMonster);
    const uint32_t missile =
        spawn_tossed(level, qc::kMoveFlyMissile, {-300, 300, -232}, {600, 0, 0});
    level.vm().set_field_int(missile, level.f().touch, level.function("count_touch"));
    level.vm().set_field_int(target, level.f().touch, level.function("count_touch"));
    for (int i = 0; i < 20 && level.global("touch_calls") == 0; ++i) ASSERT_TRUE(level.frame());
    EXPECT_EQ(level.global("touch_calls"), 2);
    // The target's touch ran second, with the missile as other.
    EXPECT_EQ(level.global_edict("touch_self"), target);
    EXPECT_EQ(level.global_edict("touch_other"), missile);
    // A missile's box against entities is -15..15 wide (MOVE_MISSILE).
    EXPECT_NEAR(level.origin(missile)[0], -200 - 16 - 15, 0.1);
}

// start.bsp's rooms are joined by a window of water: x -8..7, y 264..312, z -248..-155.
TEST(ServerPhysics, TossedItemSplashesWhenItLandsInWater) {
    PhysicsLevel level("start.bsp");
    // Thrown from the main room, it falls 48 units (0.35 s) and lands at x 1.6, in the water.
    const uint32_t e = spawn_tossed(level, qc::kMoveToss, {-40, 288, -200}, {120, 0, 0});
    level.vm().set_field_float(e, level.f().watertype, float(bsp_contents::empty));
    for (int i = 0; i < 72 * 3 && !(level.flags(e) & qc::kFlOnGround); ++i) {
        ASSERT_TRUE(level.frame());
    }
    ASSERT_TRUE(level.flags(e) & qc::kFlOnGround);
    // Quake checks for water only when a toss hits something: one splash, on the floor.
    ASSERT_EQ(level.sounds.sounds.size(), 1u);
    EXPECT_EQ(level.sounds.sounds[0].sample, "misc/h2ohit1.wav");
    EXPECT_EQ(level.vm().field_float(e, level.f().watertype), float(bsp_contents::water));
    EXPECT_EQ(level.vm().field_float(e, level.f().waterlevel), 1);
}

// ---- players ----

TEST(ServerPhysics, PlayerInWaterHasDepthThreeAndNoGravity) {
    PhysicsLevel level("start.bsp");
    level.player_spawned = 1;
    // The window's sill is 4 units up for players.
    level.place_player({0, 288, -200});
    ASSERT_TRUE(drop_to_floor(level.game, PhysicsLevel::kPlayer));
    const Vec3f start = level.origin(1);
    level.vm().set_field_vector(1, level.f().velocity, {0, 0, 0});
    for (int i = 0; i < 10; ++i) ASSERT_TRUE(level.frame());
    EXPECT_EQ(level.vm().field_float(1, level.f().waterlevel), 3);
    EXPECT_EQ(level.vm().field_float(1, level.f().watertype), float(bsp_contents::water));
    EXPECT_EQ(level.origin(1), start);
    EXPECT_EQ(level.velocity(1)[2], 0);
}

// One frame of a player's command, in the order of Quake's server frame.
bool player_frame(PhysicsLevel& level, const UserCmd& cmd) {
    apply_user_cmd(level.game, PhysicsLevel::kPlayer, cmd);
    client_think(level.game, PhysicsLevel::kPlayer, cmd);
    return level.frame();
}

float horizontal_speed(const Vec3f& v) {
    return std::sqrt(v[0] * v[0] + v[1] * v[1]);
}

TEST(ServerPhysics, RunningSpeedFollowsFrictionAndAcceleration) {
    PhysicsLevel level("start.bsp");
    level.player_spawned = 1;
    level.place_player(kPlayerStart);
    ASSERT_TRUE(drop_to_floor(level.game, PhysicsLevel::kPlayer));
    ASSERT_FLOAT_EQ(level.origin(PhysicsLevel::kPlayer)[2], kPlayerStandZ);
    UserCmd cmd;
    cmd.forward_move = 400;  // more than sv_maxspeed: wishspeed is 320
    const float dt = PhysicsLevel::kFrame;
    float speed = 0;
    for (int frame = 0; frame < 144; ++frame) {
        ASSERT_TRUE(player_frame(level, cmd));
        // speed' = speed - max(speed, stopspeed) * friction * dt, then up to wishspeed.
        const float slowed =
            speed == 0 ? 0 : std::max(0.0f, speed - std::max(speed, 100.0f) * 4 * dt);
        speed = slowed + std::min(10 * 320 * dt, 320 - slowed);
        const Vec3f v = level.velocity(PhysicsLevel::kPlayer);
        ASSERT_NEAR(horizontal_speed(v), speed, 1e-2) << "frame " << frame;
        ASSERT_NEAR(v[1], 0, 1e-3);  // facing +x
        // Stay on the same spot, so the room's walls never interfere.
        level.vm().set_field_vector(PhysicsLevel::kPlayer, level.f().origin, kPlayerStart);
        level.world.link(PhysicsLevel::kPlayer, false);
    }
    EXPECT_NEAR(speed, 320, 1e-3);
    EXPECT_TRUE(level.flags(PhysicsLevel::kPlayer) & qc::kFlOnGround);
}

TEST(ServerPhysics, FrictionStopsAnIdlePlayer) {
    PhysicsLevel level("start.bsp");
    level.player_spawned = 1;
    level.place_player(kPlayerStart);
    ASSERT_TRUE(drop_to_floor(level.game, PhysicsLevel::kPlayer));
    level.vm().set_field_vector(PhysicsLevel::kPlayer, level.f().velocity, {50, 0, 0});
    const UserCmd idle;
    ASSERT_TRUE(player_frame(level, idle));
    // Below stopspeed friction removes stopspeed * friction * dt.
    EXPECT_NEAR(level.velocity(PhysicsLevel::kPlayer)[0], 50 - 100 * 4 * PhysicsLevel::kFrame,
                1e-3);
    for (int i = 0; i < 30; ++i) ASSERT_TRUE(player_frame(level, idle));
    EXPECT_EQ(level.velocity(PhysicsLevel::kPlayer)[0], 0);
}

TEST(ServerPhysics, RunningIntoWallsNeverEndsInSolid) {
    PhysicsLevel level("start.bsp");
    level.player_spawned = 1;
    for (int dir = 0; dir < 8; ++dir) {
        level.place_player(kPlayerStart, float(dir * 45 + 10));
        ASSERT_TRUE(drop_to_floor(level.game, PhysicsLevel::kPlayer));
        UserCmd cmd;
        cmd.view_angles = {0, float(dir * 45 + 10), 0};
        cmd.forward_move = 400;
        cmd.side_move = dir % 2 ? 350 : -350;
        for (int frame = 0; frame < 72 * 3; ++frame) {
            ASSERT_TRUE(player_frame(level, cmd));
            ASSERT_FALSE(level.world.test_entity_position(PhysicsLevel::kPlayer))
                << "dir " << dir << " frame " << frame;
            ASSERT_GE(level.origin(PhysicsLevel::kPlayer)[2], kPlayerStandZ - 0.5);
        }
        // It got somewhere: into a wall or a corner.
        EXPECT_GT(std::fabs(level.origin(PhysicsLevel::kPlayer)[0] - kPlayerStart[0]) +
                      std::fabs(level.origin(PhysicsLevel::kPlayer)[1] - kPlayerStart[1]),
                  100);
    }
}

// The highest the player's origin gets walking 1.5 s into a box `height` tall lying across its
// path (x -150..-60), and how far it gets.
Vec3f walk_onto_box(float height) {
    PhysicsLevel level("start.bsp");
    level.player_spawned = 1;
    level.spawn_box({-150, 288, kFloor}, {0, -100, 0}, {90, 100, height}, qc::kMoveNone,
                    qc::kSolidBbox);
    level.place_player(kPlayerStart);
    EXPECT_TRUE(drop_to_floor(level.game, PhysicsLevel::kPlayer));
    UserCmd cmd;
    cmd.forward_move = 400;
    Vec3f highest = level.origin(PhysicsLevel::kPlayer);
    for (int frame = 0; frame < 108; ++frame) {
        EXPECT_TRUE(player_frame(level, cmd));
        const Vec3f o = level.origin(PhysicsLevel::kPlayer);
        if (o[2] > highest[2]) highest = o;
        highest[0] = std::max(highest[0], o[0]);
        EXPECT_FALSE(level.world.test_entity_position(PhysicsLevel::kPlayer)) << frame;
    }
    return highest;
}

TEST(ServerPhysics, PlayerClimbsAnEighteenUnitStep) {
    const Vec3f top = walk_onto_box(18);
    EXPECT_NEAR(top[2], kPlayerStandZ + 18, 0.1);
    EXPECT_GT(top[0], -150 + 16);
}

TEST(ServerPhysics, PlayerDoesNotClimbANineteenUnitStep) {
    const Vec3f top = walk_onto_box(19);
    EXPECT_NEAR(top[2], kPlayerStandZ, 0.1);
    EXPECT_LE(top[0], -150 - 16);
}

TEST(ServerPhysics, ClientThinkSetsBodyAnglesAndButtons) {
    PhysicsLevel level("start.bsp");
    level.place_player(kPlayerStart);
    UserCmd cmd;
    cmd.view_angles = {30, 90, 0};
    cmd.buttons = 3;
    cmd.impulse = 7;
    apply_user_cmd(level.game, PhysicsLevel::kPlayer, cmd);
    client_think(level.game, PhysicsLevel::kPlayer, cmd);
    const auto& f = level.f();
    EXPECT_EQ(level.vm().field_vector(1, f.v_angle), cmd.view_angles);
    const Vec3f angles = level.vm().field_vector(1, f.angles);
    EXPECT_FLOAT_EQ(angles[0], -10);  // a third of the pitch, negated
    EXPECT_FLOAT_EQ(angles[1], 90);
    EXPECT_EQ(level.vm().field_float(1, f.button0), 1);
    EXPECT_EQ(level.vm().field_float(1, f.button2), 1);
    EXPECT_EQ(level.vm().field_float(1, f.impulse), 7);
    // A zero impulse leaves the last one for QuakeC to consume.
    cmd.impulse = 0;
    cmd.buttons = 0;
    apply_user_cmd(level.game, PhysicsLevel::kPlayer, cmd);
    EXPECT_EQ(level.vm().field_float(1, f.impulse), 7);
    EXPECT_EQ(level.vm().field_float(1, f.button2), 0);
    // fixangle: QuakeC set the angles, the command does not override them.
    level.vm().set_field_float(1, f.fixangle, 1);
    cmd.view_angles = {0, 180, 0};
    apply_user_cmd(level.game, PhysicsLevel::kPlayer, cmd);
    client_think(level.game, PhysicsLevel::kPlayer, cmd);
    EXPECT_FLOAT_EQ(level.vm().field_vector(1, f.angles)[1], 90);
}

TEST(ServerPhysics, AirControlIsCappedAtThirtyUnits) {
    PhysicsLevel level("start.bsp");
    level.place_player({-192, 288, -150});
    level.vm().set_field_float(1, level.f().flags, qc::kFlClient);  // in the air
    UserCmd cmd;
    cmd.side_move = 350;  // to the right of yaw 0: -y
    client_think(level.game, PhysicsLevel::kPlayer, cmd);
    // One frame's air acceleration: 10 * 320 * dt (44), capped to 30 - current (0) = 30.
    EXPECT_NEAR(level.velocity(1)[1], -30, 1e-3);
    client_think(level.game, PhysicsLevel::kPlayer, cmd);
    EXPECT_NEAR(level.velocity(1)[1], -30, 1e-3);  // already at the cap
}

TEST(ServerPhysics, DeadPlayersDoNotSteer) {
    PhysicsLevel level("start.bsp");
    level.place_player(kPlayerStart);
    level.vm().set_field_float(1, level.f().health, 0);
    level.vm().set_field_vector(1, level.f().punchangle, {5, 0, 0});
    UserCmd cmd;
    cmd.forward_move = 400;
    client_think(level.game, PhysicsLevel::kPlayer, cmd);
    EXPECT_EQ(level.velocity(1), (Vec3f{0, 0, 0}));
    // The punch still fades, 10 degrees a second.
    EXPECT_NEAR(level.vm().field_vector(1, level.f().punchangle)[0], 5 - 10 * PhysicsLevel::kFrame,
                1e-4);
}

// ---- monsters falling ----

TEST(ServerPhysics, StepMonsterFallsAndLandsWithAThud) {
    PhysicsLevel level("start.bsp");
    const uint32_t e = level.spawn_box({-300, 400, -150}, {-16, -16, -24}, {16, 16, 40},
                                       qc::kMoveStep, qc::kSolidSlideBox);
    level.vm().set_field_float(e, level.f().flags, qc::kFlMonster);
    for (int i = 0; i < 72 && !(level.flags(e) & qc::kFlOnGround); ++i) ASSERT_TRUE(level.frame());
    ASSERT_TRUE(level.flags(e) & qc::kFlOnGround);
    EXPECT_NEAR(level.origin(e)[2], kFloor + 24, 0.1);
    ASSERT_EQ(level.sounds.sounds.size(), 1u);
    EXPECT_EQ(level.sounds.sounds[0].sample, "demon/dland2.wav");
    EXPECT_EQ(level.sounds.sounds[0].edict, e);
}

TEST(ServerPhysics, FlyingMonstersDoNotFall) {
    PhysicsLevel level("start.bsp");
    const uint32_t e = level.spawn_box({-300, 400, -150}, {-16, -16, -24}, {16, 16, 40},
                                       qc::kMoveStep, qc::kSolidSlideBox);
    level.vm().set_field_float(e, level.f().flags, qc::kFlMonster | qc::kFlFly);
    for (int i = 0; i < 10; ++i) ASSERT_TRUE(level.frame());
    EXPECT_FLOAT_EQ(level.origin(e)[2], -150);
}

// ---- pushers ----

// start.bsp's *1 (a breakable piece of wall: x 449..503, y 513..519, z -247..-129, world
// above it) made a pusher (model index 2) moving along y, its origin `offset_y` from the map's.
uint32_t spawn_pusher(PhysicsLevel& level, float speed_y, float offset_y = 0) {
    const Bsp& bsp = *level.bsp;
    const uint32_t e = level.spawn();
    auto& vm = level.vm();
    const auto& f = level.f();
    vm.set_field_float(e, f.modelindex, 2);
    vm.set_field_vector(e, f.mins, bsp.models[1].mins);
    vm.set_field_vector(e, f.maxs, bsp.models[1].maxs);
    vm.set_field_float(e, f.movetype, qc::kMovePush);
    vm.set_field_float(e, f.solid, qc::kSolidBsp);
    vm.set_field_vector(e, f.velocity, {0, speed_y, 0});
    vm.set_field_vector(e, f.origin, {0, offset_y, 0});
    // A pusher moves until its nextthink on its own clock, ltime.
    vm.set_field_float(e, f.ltime, 0);
    vm.set_field_float(e, f.nextthink, 10);
    vm.set_field_int(e, f.think, level.function("count_think"));
    vm.set_field_int(e, f.blocked, level.function("count_blocked"));
    level.world.link(e, false);
    return e;
}

uint32_t spawn_crate(PhysicsLevel& level, const Vec3f& origin) {
    const uint32_t e =
        level.spawn_box(origin, {-16, -16, 0}, {16, 16, 32}, qc::kMoveToss, qc::kSolidBbox);
    EXPECT_TRUE(drop_to_floor(level.game, e));
    return e;
}

TEST(ServerPhysics, PusherShovesABoxInItsWay) {
    PhysicsLevel level("start.bsp");
    const uint32_t pusher = spawn_pusher(level, -100);
    const uint32_t crate = spawn_crate(level, {476, 470, kFloor});
    for (int frame = 0; frame < 72; ++frame) {
        ASSERT_TRUE(level.frame());
        ASSERT_FALSE(level.world.test_entity_position(crate)) << frame;
    }
    const float moved = -100 * 72 * PhysicsLevel::kFrame;  // one second at 100 units/s
    EXPECT_NEAR(level.origin(pusher)[1], moved, 1e-2);
    EXPECT_NEAR(level.vm().field_float(pusher, level.f().ltime), 1.0f, 1e-4);
    // The crate ends just ahead of the wall's front (y 513 - 100): pushed once the boxes,
    // grown by 1 when linked, come within a frame's move (1.4) of touching.
    const float crate_front = level.origin(crate)[1] + 16;
    EXPECT_LE(crate_front, 513 + moved + 0.01);
    EXPECT_GE(crate_front, 513 + moved - 3.5);
    EXPECT_FLOAT_EQ(level.origin(crate)[0], 476);
    EXPECT_EQ(level.global("blocked_calls"), 0);
}

TEST(ServerPhysics, BlockedPusherStopsAndCallsBlocked) {
    PhysicsLevel level("start.bsp");
    const uint32_t pusher = spawn_pusher(level, 100);  // toward the back wall (y 632)
    const uint32_t crate = spawn_crate(level, {476, 580, kFloor});
    for (int frame = 0; frame < 144; ++frame) {
        ASSERT_TRUE(level.frame());
        ASSERT_FALSE(level.world.test_entity_position(crate)) << frame;
    }
    EXPECT_GT(level.global("blocked_calls"), 0);
    EXPECT_EQ(level.global_edict("blocked_self"), pusher);
    EXPECT_EQ(level.global_edict("blocked_other"), crate);
    // Pinned between the wall (y 632) and the pusher; the pusher's clock stopped with it.
    EXPECT_NEAR(level.origin(crate)[1] + 16, 632, 0.1);
    const float travelled = level.origin(pusher)[1];
    EXPECT_LE(519 + travelled, 632 - 32 + 0.01);
    EXPECT_GE(519 + travelled, 632 - 32 - 3.5);
    EXPECT_NEAR(level.vm().field_float(pusher, level.f().ltime), travelled / 100, 1e-3);
}

TEST(ServerPhysics, PusherCarriesRidersAndThinksAtItsTime) {
    PhysicsLevel level("start.bsp");
    // Out in the room (y 413..419), with nothing but air above it.
    const uint32_t pusher = spawn_pusher(level, -100, -100);
    level.vm().set_field_float(pusher, level.f().nextthink, 0.5f);
    // A crate standing on the pusher is moved though it does not overlap it. A walking one:
    // others lose their footing when carried.
    const uint32_t rider = spawn_crate(level, {476, 416, -100});
    ASSERT_EQ(level.vm().field_int(rider, level.f().groundentity),
              int32_t(level.vm().entity_value(pusher)));
    ASSERT_NEAR(level.origin(rider)[2], -128, 0.1);  // the brush's top (bounds grow by 1)
    level.vm().set_field_float(rider, level.f().movetype, qc::kMoveWalk);
    const float rider_y = level.origin(rider)[1];
    for (int frame = 0; frame < 72 && level.global("think_calls") == 0; ++frame) {
        ASSERT_TRUE(level.frame());
    }
    ASSERT_EQ(level.global("think_calls"), 1);
    EXPECT_EQ(level.global_edict("think_self"), pusher);
    // It moved exactly to its think time: 0.5 s at 100 units/s.
    EXPECT_NEAR(level.origin(pusher)[1], -150, 1e-2);
    EXPECT_NEAR(level.origin(rider)[1], rider_y - 50, 1e-2);
}

}  // namespace
}  // namespace nq::server::test

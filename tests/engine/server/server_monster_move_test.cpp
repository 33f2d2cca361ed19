// Monster movement (monster_move.h) on real maps: steps that stay on the ground, climb 18 units
// and no more, stop at ledges (check_bottom), flyers closing in on their enemy's height,
// swimmers kept in water, droptofloor, changeyaw, and a deterministic chase with movetogoal.
#include <gtest/gtest.h>

#include <cmath>

#include "server/monster_move.h"
#include "server_physics_fixture.h"

namespace nq::server::test {
namespace {

constexpr float kStartFloor = -248;  // start.bsp's floor

uint32_t spawn_monster(PhysicsLevel& level, const Vec3f& origin, int flags,
                       const Vec3f& mins = {-16, -16, -24}, const Vec3f& maxs = {16, 16, 40}) {
    const uint32_t e = level.spawn_box(origin, mins, maxs, qc::kMoveStep, qc::kSolidSlideBox);
    level.vm().set_field_float(e, level.f().flags, float(flags | qc::kFlMonster));
    level.vm().set_field_float(e, level.f().yaw_speed, 20);
    return e;
}

uint32_t spawn_walker(PhysicsLevel& level, const Vec3f& origin) {
    const uint32_t e = spawn_monster(level, origin, 0);
    EXPECT_TRUE(drop_to_floor(level.game, e));
    return e;
}

TEST(MonsterMove, WalkMoveOnFlatGroundMovesExactly) {
    PhysicsLevel level("start.bsp");
    const uint32_t e = spawn_walker(level, {-300, 400, -200});
    const Vec3f start = level.origin(e);
    EXPECT_NEAR(start[2], kStartFloor + 24, 0.05);
    ASSERT_TRUE(walk_move(level.game, e, 90, 10, true));
    EXPECT_NEAR(level.origin(e)[0], start[0], 1e-4);
    EXPECT_NEAR(level.origin(e)[1], start[1] + 10, 1e-4);
    EXPECT_NEAR(level.origin(e)[2], start[2], 0.05);
    EXPECT_TRUE(check_bottom(level.game, e));
}

TEST(MonsterMove, OnlyGroundedFlyingOrSwimmingMonstersWalk) {
    PhysicsLevel level("start.bsp");
    const uint32_t e = spawn_monster(level, {-300, 400, -200}, 0);  // in the air
    EXPECT_FALSE(walk_move(level.game, e, 0, 10, true));
    EXPECT_EQ(level.origin(e), (Vec3f{-300, 400, -200}));
}

// A box `height` tall in front of a walker: it steps up onto it, or not.
bool steps_onto_box(float height, float& rise) {
    PhysicsLevel level("start.bsp");
    const uint32_t e = spawn_walker(level, {-300, 400, -200});
    level.spawn_box({-280, 400, kStartFloor}, {0, -40, 0}, {60, 40, height}, qc::kMoveNone,
                    qc::kSolidBbox);
    const float z = level.origin(e)[2];
    bool moved = false;
    for (int i = 0; i < 4; ++i) moved = walk_move(level.game, e, 0, 8, true);
    rise = level.origin(e)[2] - z;
    return moved;
}

TEST(MonsterMove, StepsUpEighteenUnitsButNotNineteen) {
    float rise = 0;
    EXPECT_TRUE(steps_onto_box(18, rise));
    EXPECT_NEAR(rise, 18, 0.05);
    EXPECT_FALSE(steps_onto_box(19, rise));
    EXPECT_NEAR(rise, 0, 0.05);
}

// lq1m1: a floor at z 256 ends at x -976.5 (around y -1100); the floor below is at z 80.
TEST(MonsterMove, WalkMoveStopsAtALedge) {
    PhysicsLevel level("lq1m1.bsp");
    ASSERT_EQ(level.world.point_contents({-976, -1100, 255}), bsp_contents::solid);
    ASSERT_EQ(level.world.point_contents({-977, -1100, 255}), bsp_contents::empty);
    ASSERT_EQ(level.world.point_contents({-977, -1100, 100}), bsp_contents::empty);
    const uint32_t e = spawn_walker(level, {-940, -1100, 300});
    ASSERT_NEAR(level.origin(e)[2], 256 + 24, 0.05);
    int steps = 0;
    while (steps < 20 && walk_move(level.game, e, 180, 4, true)) ++steps;
    ASSERT_LT(steps, 20);
    EXPECT_GE(steps, 3);
    // It stopped with its box still over the ledge, and the failed step left it in place.
    const Vec3f stop = level.origin(e);
    EXPECT_NEAR(stop[0] - 16, -977, 4.5);
    EXPECT_TRUE(check_bottom(level.game, e));
    EXPECT_FALSE(walk_move(level.game, e, 180, 4, true));
    EXPECT_EQ(level.origin(e), stop);
    // Half over the edge, the corners dangle.
    level.vm().set_field_vector(e, level.f().origin, {-976, -1100, stop[2]});
    EXPECT_FALSE(check_bottom(level.game, e));
    // A monster whose ground was pulled away (FL_PARTIALGROUND) may walk off and fall.
    level.vm().set_field_vector(e, level.f().origin, stop);
    level.vm().set_field_float(e, level.f().flags,
                               float(qc::kFlMonster | qc::kFlOnGround | qc::kFlPartialGround));
    EXPECT_TRUE(walk_move(level.game, e, 180, 40, true));
    EXPECT_FALSE(level.flags(e) & qc::kFlOnGround);
}

TEST(MonsterMove, FlyersRiseTowardTheirEnemy) {
    PhysicsLevel level("start.bsp");
    const uint32_t enemy = level.spawn_box({-100, 300, -100}, {-16, -16, -24}, {16, 16, 32},
                                           qc::kMoveNone, qc::kSolidNot);
    const uint32_t e = spawn_monster(level, {-300, 300, -200}, qc::kFlFly);
    level.vm().set_field_int(e, level.f().enemy, int32_t(level.vm().entity_value(enemy)));
    ASSERT_TRUE(walk_move(level.game, e, 0, 8, true));
    // 100 below the enemy (less than 30): 8 up with the step.
    EXPECT_NEAR(level.origin(e)[0], -292, 1e-4);
    EXPECT_FLOAT_EQ(level.origin(e)[2], -192);
}

// start.bsp's rooms are joined by a window of water: x -8..7, y 256..320, z -248..-160.
TEST(MonsterMove, SwimmersStayInWater) {
    PhysicsLevel level("start.bsp");
    const uint32_t e = spawn_monster(level, {0, 288, -220}, qc::kFlSwim, {-8, -8, -8}, {8, 8, 8});
    ASSERT_EQ(level.world.point_contents(level.origin(e)), bsp_contents::water);
    EXPECT_TRUE(walk_move(level.game, e, 90, 4, true));     // along the window
    EXPECT_FALSE(walk_move(level.game, e, 180, 16, true));  // out into the air
    EXPECT_NEAR(level.origin(e)[0], 0, 1e-4);
}

TEST(MonsterMove, DropToFloor) {
    PhysicsLevel level("start.bsp");
    const uint32_t high = spawn_monster(level, {-300, 400, kStartFloor + 24 + 300}, 0);
    EXPECT_FALSE(drop_to_floor(level.game, high));  // more than 256 to fall
    EXPECT_EQ(level.origin(high)[2], kStartFloor + 24 + 300);
    const uint32_t in_wall = spawn_monster(level, {-300, 700, -200}, 0);  // outside the map
    EXPECT_FALSE(drop_to_floor(level.game, in_wall));
    const uint32_t near = spawn_monster(level, {-300, 300, -100}, 0);
    ASSERT_TRUE(drop_to_floor(level.game, near));
    EXPECT_NEAR(level.origin(near)[2], kStartFloor + 24, 0.05);
    EXPECT_TRUE(level.flags(near) & qc::kFlOnGround);
    EXPECT_EQ(level.vm().field_int(near, level.f().groundentity), 0);
}

TEST(MonsterMove, ChangeYawTurnsTheShortWayAtYawSpeed) {
    PhysicsLevel level("start.bsp");
    const uint32_t e = spawn_monster(level, {-300, 400, -200}, 0);
    auto& vm = level.vm();
    vm.set_field_vector(e, level.f().angles, {0, 350, 0});
    vm.set_field_float(e, level.f().ideal_yaw, 10);
    vm.set_field_float(e, level.f().yaw_speed, 15);
    change_yaw(level.game, e);
    EXPECT_NEAR(vm.field_vector(e, level.f().angles)[1], 5, 0.01);  // through 360
    change_yaw(level.game, e);
    EXPECT_NEAR(vm.field_vector(e, level.f().angles)[1], 10, 0.01);
}

Vec3f chase(uint32_t seed, float& start_distance, float& end_distance) {
    PhysicsLevel level("start.bsp");
    GameRandom random(seed);
    const uint32_t goal = level.spawn_box({-60, 560, -224}, {-16, -16, -24}, {16, 16, 32},
                                          qc::kMoveNone, qc::kSolidSlideBox);
    const uint32_t e = spawn_walker(level, {-420, 80, -200});
    auto& vm = level.vm();
    vm.set_field_int(e, level.f().goalentity, int32_t(vm.entity_value(goal)));
    vm.set_field_int(e, level.f().enemy, int32_t(vm.entity_value(goal)));
    auto distance = [&] {
        const Vec3f a = level.origin(e), b = level.origin(goal);
        return std::hypot(a[0] - b[0], a[1] - b[1]);
    };
    start_distance = distance();
    for (int i = 0; i < 120; ++i) {
        move_to_goal(level.game, e, 8, random);
        EXPECT_FALSE(level.world.test_entity_position(e)) << i;
    }
    end_distance = distance();
    EXPECT_TRUE(check_bottom(level.game, e));
    return level.origin(e);
}

TEST(MonsterMove, MoveToGoalClosesInAndRepeatsWithTheSameSeed) {
    float start = 0, end = 0;
    const Vec3f first = chase(7, start, end);
    EXPECT_LT(end, start - 300) << start << " -> " << end;
    float start2 = 0, end2 = 0;
    EXPECT_EQ(chase(7, start2, end2), first);
}

}  // namespace
}  // namespace nq::server::test

// Server physics allocates nothing per frame once running: a walking player, a pusher shoving a
// crate, a bouncing grenade and a chasing monster over a few seconds of frames.
#include <gtest/gtest.h>

#include "server/monster_move.h"
#include "server/player_move.h"
#include "support/allocation_counter.h"
#include "server_physics_fixture.h"

namespace nq::server::test {
namespace {

TEST(ServerPhysicsAlloc, FramesAllocateNothing) {
    PhysicsLevel level("start.bsp");
    auto& vm = level.vm();
    const auto& f = level.f();
    level.player_spawned = 1;
    level.place_player({-192, 288, -224});
    // *1, a piece of wall, pushing a crate along y.
    const uint32_t pusher = level.spawn();
    vm.set_field_float(pusher, f.modelindex, 2);
    vm.set_field_vector(pusher, f.mins, level.bsp->models[1].mins);
    vm.set_field_vector(pusher, f.maxs, level.bsp->models[1].maxs);
    vm.set_field_float(pusher, f.movetype, qc::kMovePush);
    vm.set_field_float(pusher, f.solid, qc::kSolidBsp);
    vm.set_field_vector(pusher, f.velocity, {0, -60, 0});
    vm.set_field_float(pusher, f.nextthink, 100);
    vm.set_field_int(pusher, f.think, level.function("count_think"));
    level.world.link(pusher, false);
    level.spawn_box({476, 470, -248}, {-16, -16, 0}, {16, 16, 32}, qc::kMoveToss, qc::kSolidBbox);
    const uint32_t grenade =
        level.spawn_box({-300, 300, -150}, {}, {}, qc::kMoveBounce, qc::kSolidBbox);
    vm.set_field_vector(grenade, f.velocity, {80, 40, 250});
    const uint32_t monster = level.spawn_box({-420, 80, -224}, {-16, -16, -24}, {16, 16, 40},
                                             qc::kMoveStep, qc::kSolidSlideBox);
    vm.set_field_float(monster, f.flags, qc::kFlMonster | qc::kFlOnGround);
    vm.set_field_float(monster, f.yaw_speed, 20);
    vm.set_field_int(monster, f.goalentity, int32_t(vm.entity_value(PhysicsLevel::kPlayer)));
    GameRandom random(3);
    UserCmd cmd;
    cmd.forward_move = 400;
    cmd.side_move = 200;
    auto frame = [&](int i) {
        cmd.view_angles[1] = float(i % 360);
        apply_user_cmd(level.game, PhysicsLevel::kPlayer, cmd);
        client_think(level.game, PhysicsLevel::kPlayer, cmd);
        move_to_goal(level.game, monster, 8, random);
        ASSERT_TRUE(level.frame());
    };
    for (int i = 0; i < 10; ++i) frame(i);
    const long before = ::nq::test::g_allocations.load();
    for (int i = 10; i < 300; ++i) frame(i);
    EXPECT_EQ(::nq::test::g_allocations.load() - before, 0);
    EXPECT_LT(level.origin(pusher)[1], -60 * 4);  // it did move
}

}  // namespace
}  // namespace nq::server::test

// The game as a player meets it, through the server with the real LibreQuake progs: running
// forward follows Quake's friction and acceleration, a monster that sees the player comes for
// it, shooting one kills it, an item changes the player's stats, and touching the exit asks
// for the next level.
#include <gtest/gtest.h>

#include <cmath>

#include "common/file_io.h"
#include "formats/bsp.h"
#include "server/progs_layout.h"
#include "server/server.h"
#include "server/server_commands.h"
#include "server/server_level.h"
#include "support/data_server_host.h"
#include "support/test_data.h"

namespace nq::server {
namespace {

constexpr uint32_t kPlayer = 1;
constexpr double kFrame = 1.0 / 72;

using DataHost = test::DataServerHost;

struct Game {
    DataHost host;
    Server server{host};
    ServerLevel* level = nullptr;

    explicit Game(const char* map) {
        const SpawnResult r = server.spawn(map, {});
        EXPECT_TRUE(r.error.empty()) << r.error;
        level = server.level();
    }
    vm::Vm& vm() { return *level->vm; }
    const FieldOffsets& f() { return level->layout.fields; }
    vm::Vec3f origin(uint32_t e) { return vm().field_vector(e, f().origin); }
    bool run(int frames, const UserCmd& cmd = {}) {
        for (int i = 0; i < frames; ++i) {
            if (!server.frame(kFrame, cmd)) {
                ADD_FAILURE() << server.error();
                return false;
            }
        }
        return true;
    }
    std::vector<uint32_t> find(std::string_view classname) {
        std::vector<uint32_t> out;
        for (uint32_t e = 1; e < vm().num_edicts(); ++e) {
            if (level->edicts.is_free(e)) continue;
            if (vm().string_or_empty(vm().field_int(e, f().classname)) == classname)
                out.push_back(e);
        }
        return out;
    }
    // Whether a player-sized box moves from `from` to `to` with nothing (walls, doors, other
    // entities) in between.
    bool clear_path(const vm::Vec3f& from, const vm::Vec3f& to, uint32_t ignore) {
        const MoveTrace t =
            level->world.move(from, {-16, -16, -24}, {16, 16, 32}, to, MoveKind::normal, ignore);
        return t.fraction == 1 && !t.start_solid;
    }
    void place_player(const vm::Vec3f& at) {
        vm().set_field_vector(kPlayer, f().origin, at);
        vm().set_field_vector(kPlayer, f().velocity, {0, 0, 0});
        level->world.link(kPlayer, false);
    }
};

float flat_distance(const vm::Vec3f& a, const vm::Vec3f& b) {
    return std::hypot(a[0] - b[0], a[1] - b[1]);
}

float yaw_towards(const vm::Vec3f& from, const vm::Vec3f& to) {
    return float(std::atan2(to[1] - from[1], to[0] - from[0]) * 180 / M_PI);
}

// The horizontal speed after each frame of holding forward from rest, by Quake's
// SV_UserFriction then SV_Accelerate, with the default cvars.
std::vector<float> forward_speeds(int frames, float wish) {
    const float dt = float(kFrame), friction = 4, stop = 100, accelerate = 10;
    wish = std::min(wish, 320.0f);
    std::vector<float> speeds;
    float speed = 0;
    for (int i = 0; i < frames; ++i) {
        if (speed > 0) {
            const float drop = std::max(speed, stop) * friction * dt;
            speed = std::max(speed - drop, 0.0f);
        }
        const float add = wish - speed;
        if (add > 0) speed += std::min(accelerate * dt * wish, add);
        speeds.push_back(speed);
    }
    return speeds;
}

TEST(ServerGameplay, RunningForwardFollowsQuakesFrictionAndAcceleration) {
    const int frames = 144;  // 2 s
    const std::vector<float> speeds = forward_speeds(frames, 400);
    float expected = 0;
    for (float s : speeds) expected += s * float(kFrame);
    // The first map whose player start has a clear run long enough, found with the map's own
    // player hull.
    for (const char* map : {"start", "lq1m1", "e2m3"}) {
        Game game(map);
        ASSERT_TRUE(game.run(10));  // settle on the floor
        const vm::Vec3f start = game.origin(kPlayer);
        float best_yaw = 0, best_length = 0;
        for (int k = 0; k < 16; ++k) {
            const float yaw = float(k) * 22.5f, r = float(yaw * M_PI / 180);
            const vm::Vec3f end = {start[0] + 900 * std::cos(r), start[1] + 900 * std::sin(r),
                                   start[2]};
            const BspTrace t = trace_hull(*game.level->bsp, 1, start, end);
            if (t.fraction * 900 > best_length) {
                best_length = t.fraction * 900;
                best_yaw = yaw;
            }
        }
        if (best_length < expected + 40) continue;
        UserCmd cmd;
        cmd.view_angles = {0, best_yaw, 0};
        cmd.forward_move = 400;
        ASSERT_TRUE(game.run(frames, cmd));
        const vm::Vec3f end = game.origin(kPlayer);
        const vm::Vec3f v = game.vm().field_vector(kPlayer, game.f().velocity);
        EXPECT_NEAR(std::hypot(v[0], v[1]), speeds.back(), 0.5f) << map;
        EXPECT_NEAR(std::hypot(end[0] - start[0], end[1] - start[1]), expected, 2.0f) << map;
        EXPECT_NE(point_contents(*game.level->bsp, 0, end), bsp_contents::solid) << map;
        return;
    }
    FAIL() << "no player start with a clear run of " << expected + 40 << " units";
}

TEST(ServerGameplay, AMonsterThatSeesThePlayerComesForIt) {
    Game game("lq1m1");
    ASSERT_TRUE(game.run(36));
    toggle_god(*game.level);
    // A dog (it only bites, so it must come close) with a clear, level path to a spot 320
    // units away.
    for (const char* kind : {"monster_dog"}) {
        for (uint32_t m : game.find(kind)) {
            const vm::Vec3f at = game.origin(m);
            for (int k = 0; k < 8; ++k) {
                const float r = float(k * M_PI / 4);
                const vm::Vec3f spot = {at[0] + 320 * std::cos(r), at[1] + 320 * std::sin(r),
                                        at[2]};
                if (!game.clear_path(at, spot, m)) continue;
                game.place_player(spot);
                UserCmd look;
                look.view_angles = {0, yaw_towards(spot, at), 0};
                const float before = flat_distance(game.origin(m), game.origin(kPlayer));
                ASSERT_TRUE(game.run(3 * 72, look));
                const float after = flat_distance(game.origin(m), game.origin(kPlayer));
                const uint32_t enemy =
                    game.vm()
                        .edict_of(uint32_t(game.vm().field_int(m, game.f().enemy)))
                        .value_or(0);
                EXPECT_EQ(enemy, kPlayer) << kind << " never noticed the player";
                EXPECT_LT(after, before - 40) << kind << " did not come closer";
                return;
            }
        }
    }
    FAIL() << "no monster with a clear spot near it";
}

TEST(ServerGameplay, ShootingAMonsterKillsItAndTheCountRises) {
    Game game("lq1m1");
    ASSERT_TRUE(game.run(36));
    toggle_god(*game.level);
    const GlobalOffsets& g = game.level->layout.globals;
    const float killed_before = game.vm().global_float(g.killed_monsters);
    std::vector<uint32_t> grunts = game.find("monster_army");
    ASSERT_FALSE(grunts.empty());
    const uint32_t grunt = grunts.front();
    const vm::Vec3f at = game.origin(grunt);
    // Stand 96 units away on the side with a clear line, shotgun in hand, and fire.
    for (int k = 0; k < 8; ++k) {
        const float r = float(k * M_PI / 4);
        const vm::Vec3f spot = {at[0] + 96 * std::cos(r), at[1] + 96 * std::sin(r), at[2]};
        if (!game.clear_path(at, spot, grunt)) continue;
        game.place_player(spot);
        for (int shot = 0; shot < 20 && game.vm().global_float(g.killed_monsters) == killed_before;
             ++shot) {
            UserCmd fire;
            const vm::Vec3f target = game.origin(grunt);
            fire.view_angles = {0, yaw_towards(game.origin(kPlayer), target), 0};
            fire.buttons = 1;
            ASSERT_TRUE(game.run(36, fire));
        }
        EXPECT_EQ(game.vm().global_float(g.killed_monsters), killed_before + 1)
            << "shells " << game.vm().field_float(kPlayer, game.f().ammo_shells) << " weapon "
            << game.vm().field_float(kPlayer, game.f().weapon) << " items "
            << game.vm().field_float(kPlayer, game.f().items) << " player at "
            << game.origin(kPlayer)[0] << " " << game.origin(kPlayer)[1] << " "
            << game.origin(kPlayer)[2] << " grunt at " << at[0] << " " << at[1] << " " << at[2]
            << " health " << game.vm().field_float(kPlayer, game.f().health);  // on failure
        EXPECT_LE(game.vm().field_float(grunt, game.f().health), 0.0f);
        return;
    }
    FAIL() << "no clear spot beside the grunt";
}

TEST(ServerGameplay, PickingUpAnItemChangesTheStats) {
    Game game("start");
    ASSERT_TRUE(game.run(10));
    std::vector<uint32_t> boxes = game.find("item_shells");
    ASSERT_FALSE(boxes.empty());
    const float shells = game.vm().field_float(kPlayer, game.f().ammo_shells);
    const vm::Vec3f at = game.origin(boxes.front());
    game.place_player({at[0] + 16, at[1] + 16, at[2] + 24});
    ASSERT_TRUE(game.run(10));
    EXPECT_GT(game.vm().field_float(kPlayer, game.f().ammo_shells), shells);
    const uint32_t box = boxes.front();
    EXPECT_TRUE(game.level->edicts.is_free(box) ||
                game.vm().string_or_empty(game.vm().field_int(box, game.f().model)).empty())
        << "the box should be taken";
}

TEST(ServerGameplay, TheExitOfLq1m1AsksForItsNextMap) {
    Game game("lq1m1");
    ASSERT_TRUE(game.run(10));
    toggle_god(*game.level);
    std::vector<uint32_t> exits = game.find("trigger_changelevel");
    ASSERT_FALSE(exits.empty());
    const uint32_t exit = exits.front();
    const vm::Vec3f mins = game.vm().field_vector(exit, game.f().absmin);
    const vm::Vec3f maxs = game.vm().field_vector(exit, game.f().absmax);
    game.place_player({(mins[0] + maxs[0]) / 2, (mins[1] + maxs[1]) / 2, (mins[2] + maxs[2]) / 2});
    // Intermission first; a button press after it ends asks for the next map.
    std::optional<std::string> next;
    UserCmd press;
    press.buttons = 1;
    for (int i = 0; i < 12 * 72 && !next; ++i) {
        ASSERT_TRUE(game.run(1, (i / 36) % 2 ? press : UserCmd{}));
        next = game.server.take_changelevel();
    }
    ASSERT_TRUE(next);
    const std::string wanted = std::string(game.vm().string_or_empty(
        game.vm().field_int(exit, game.vm().progs().find_field("map")->offset)));
    EXPECT_EQ(*next, wanted);
    EXPECT_TRUE(game.run(10));  // the level goes on until someone changes it
}

TEST(ServerGameplay, ChangingLevelCarriesThePlayersHealthAndAmmo) {
    Game game("lq1m1");
    ASSERT_TRUE(game.run(10));
    game.vm().set_field_float(kPlayer, game.f().health, 70);
    game.vm().set_field_float(kPlayer, game.f().ammo_shells, 50);
    game.vm().set_field_float(kPlayer, game.f().ammo_nails, 40);
    const SpawnResult r = game.server.spawn("start", {}, SpawnParms::carried);
    ASSERT_TRUE(r.error.empty()) << r.error;
    ServerLevel& next = *game.server.level();
    const FieldOffsets& f = next.layout.fields;
    // id's SetChangeParms keeps health between 50 and 100 and the ammo as it was.
    EXPECT_EQ(next.vm->field_float(kPlayer, f.health), 70.0f);
    EXPECT_EQ(next.vm->field_float(kPlayer, f.ammo_shells), 50.0f);
    EXPECT_EQ(next.vm->field_float(kPlayer, f.ammo_nails), 40.0f);
    // Restarting the level gives back the parms the player entered it with.
    next.vm->set_field_float(kPlayer, f.health, 20);
    ASSERT_TRUE(game.server.spawn("start", {}, SpawnParms::restart).error.empty());
    ServerLevel& again = *game.server.level();
    EXPECT_EQ(again.vm->field_float(kPlayer, again.layout.fields.health), 70.0f);
    EXPECT_EQ(again.vm->field_float(kPlayer, again.layout.fields.ammo_shells), 50.0f);
    // A new game starts from SetNewParms instead.
    ASSERT_TRUE(game.server.spawn("start", {}, SpawnParms::fresh).error.empty());
    ServerLevel& fresh = *game.server.level();
    EXPECT_EQ(fresh.vm->field_float(kPlayer, fresh.layout.fields.health), 100.0f);
}

}  // namespace
}  // namespace nq::server

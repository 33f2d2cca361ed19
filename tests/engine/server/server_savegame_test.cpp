// Saved games on real LibreQuake data: a game played for a second, changed, saved and loaded
// into a fresh server comes back as it was (player, monsters, globals), saving it again gives
// the same text, a save written in QuakeSpasm's layout loads, and malformed saves are clear
// errors naming the file and the offset.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>

#include "common/file_io.h"
#include "formats/message_decoder.h"
#include "server/progs_layout.h"
#include "server/savegame.h"
#include "server/server.h"
#include "server/server_level.h"
#include "support/data_server_host.h"
#include "support/synth_sav.h"
#include "support/test_data.h"

namespace nq::server {
namespace {

constexpr uint32_t kPlayer = 1;

using TestHost = test::DataServerHost;

std::string function_name(const ServerLevel& level, uint32_t edict, uint32_t field) {
    return std::string(level.vm->progs().function_name(level.vm->field_int(edict, field)));
}

uint32_t enemy_of(const ServerLevel& level, uint32_t edict) {
    return uint32_t(level.vm->field_int(edict, level.layout.fields.enemy)) /
           level.vm->entity_value(1);
}

std::vector<uint32_t> monsters(const ServerLevel& level) {
    std::vector<uint32_t> out;
    for (uint32_t e = 1; e < level.vm->num_edicts(); ++e) {
        if (level.edicts.is_free(e)) continue;
        if (int(level.vm->field_float(e, level.layout.fields.flags)) & qc::kFlMonster) {
            out.push_back(e);
        }
    }
    return out;
}

// A game of 'start' played for a second with the player running forward, then changed the way
// a fight would change it.
class PlayedGame : public ::testing::Test {
  protected:
    void SetUp() override {
        ASSERT_TRUE(server.spawn("start", {}).error.empty()) << host.console;
        ServerLevel& level = *server.level();
        UserCmd cmd;
        cmd.forward_move = 400;
        cmd.view_angles = level.vm->field_vector(kPlayer, level.layout.fields.angles);
        for (int i = 0; i < 72; ++i) ASSERT_TRUE(server.frame(1.0 / 72, cmd)) << server.error();
        vm::Vm& vm = *level.vm;
        const FieldOffsets& f = level.layout.fields;
        vm.set_field_float(kPlayer, f.health, 73);
        vm.set_field_float(kPlayer, f.ammo_shells, 17);
        vm.set_field_float(kPlayer, f.ammo_nails, 42);
        vm.set_field_float(kPlayer, f.ammo_rockets, 5);
        vm.set_field_float(kPlayer, f.ammo_cells, 11);
        vm.set_field_float(kPlayer, f.items, vm.field_float(kPlayer, f.items) + 2 + 4 + 32);
        const std::vector<uint32_t> found = monsters(level);
        ASSERT_GE(found.size(), 2u);
        vm.set_field_float(found[0], f.health, 12);
        vm.set_field_int(found[0], f.enemy, int32_t(vm.entity_value(kPlayer)));
        vm.set_field_float(found[1], f.frame, 3);
        vm.set_global_float(level.layout.globals.killed_monsters, 2);
        text = write_savegame(level, savegame_comment(level), 1);
    }

    Server& load(Server& fresh) {
        auto game = read_savegame(text, "test.sav");
        EXPECT_TRUE(game) << (game ? "" : game.error().to_string());
        if (!game) return fresh;
        const SpawnResult result = fresh.load_game(*game, {});
        EXPECT_TRUE(result.error.empty()) << result.error << host.console;
        return fresh;
    }

    TestHost host;
    Server server{host};
    std::string text;
};

TEST_F(PlayedGame, LoadRestoresThePlayer) {
    Server fresh(host);
    ASSERT_TRUE(load(fresh).active());
    const ServerLevel& a = *server.level();
    const ServerLevel& b = *fresh.level();
    const FieldOffsets& f = a.layout.fields;
    for (uint32_t field : {f.health, f.ammo_shells, f.ammo_nails, f.ammo_rockets, f.ammo_cells,
                           f.items, f.currentammo, f.weapon, f.armorvalue}) {
        EXPECT_EQ(b.vm->field_float(kPlayer, field), a.vm->field_float(kPlayer, field)) << field;
    }
    EXPECT_EQ(b.vm->field_float(kPlayer, f.health), 73);
    EXPECT_EQ(b.vm->field_float(kPlayer, f.ammo_cells), 11);
    const vm::Vec3f moved = a.vm->field_vector(kPlayer, f.origin);
    const vm::Vec3f restored = b.vm->field_vector(kPlayer, f.origin);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(restored[i], moved[i], 1e-5f);
    EXPECT_EQ(b.client.spawn_parms, a.client.spawn_parms);
    EXPECT_TRUE(b.world.linked(kPlayer));
}

TEST_F(PlayedGame, LoadRestoresTheMonstersAndGlobals) {
    Server fresh(host);
    ASSERT_TRUE(load(fresh).active());
    const ServerLevel& a = *server.level();
    const ServerLevel& b = *fresh.level();
    const FieldOffsets& f = a.layout.fields;
    const std::vector<uint32_t> found = monsters(a);
    ASSERT_EQ(monsters(b), found);
    for (uint32_t m : found) {
        SCOPED_TRACE(m);
        EXPECT_EQ(b.vm->field_float(m, f.health), a.vm->field_float(m, f.health));
        EXPECT_EQ(b.vm->field_float(m, f.frame), a.vm->field_float(m, f.frame));
        EXPECT_EQ(function_name(b, m, f.think), function_name(a, m, f.think));
        EXPECT_FALSE(function_name(b, m, f.think).empty());
        EXPECT_EQ(enemy_of(b, m), enemy_of(a, m));
        const vm::Vec3f pa = a.vm->field_vector(m, f.origin), pb = b.vm->field_vector(m, f.origin);
        for (int i = 0; i < 3; ++i) EXPECT_NEAR(pb[i], pa[i], 1e-4f);
        EXPECT_TRUE(b.world.linked(m) || int(a.vm->field_float(m, f.solid)) == qc::kSolidNot);
    }
    EXPECT_EQ(b.vm->field_float(found[0], f.health), 12);
    EXPECT_EQ(enemy_of(b, found[0]), kPlayer);
    const GlobalOffsets& g = a.layout.globals;
    EXPECT_EQ(b.vm->global_float(g.killed_monsters), 2);
    EXPECT_EQ(b.vm->global_float(g.total_monsters), a.vm->global_float(g.total_monsters));
    EXPECT_FLOAT_EQ(b.vm->global_float(g.time), a.vm->global_float(g.time));
    EXPECT_NEAR(fresh.time(), server.time(), 1e-6);
    EXPECT_EQ(b.vm->num_edicts(), a.vm->num_edicts());
}

TEST_F(PlayedGame, SavingTheLoadedGameGivesTheSameText) {
    Server fresh(host);
    ASSERT_TRUE(load(fresh).active());
    const ServerLevel& level = *fresh.level();
    EXPECT_EQ(write_savegame(level, savegame_comment(level), 1), text);
}

TEST_F(PlayedGame, TheLoadedGameSignsOnAndRuns) {
    Server fresh(host);
    ASSERT_TRUE(load(fresh).active());
    protocol::ProtocolState state;
    std::vector<int> signons;
    for (const std::vector<uint8_t>& block : fresh.client_messages()) {
        auto decoded = decode_server_message(block, {"server", 0, 0}, state);
        ASSERT_TRUE(decoded) << decoded.error().to_string();
        for (const DecodedMessage& m : decoded->messages) {
            if (auto* s = std::get_if<svc::SignonNum>(&m.message)) signons.push_back(s->stage);
        }
    }
    EXPECT_EQ(signons, (std::vector<int>{1, 2, 3}));
    const double saved = fresh.time();
    UserCmd cmd;
    cmd.forward_move = 400;
    for (int i = 0; i < 72; ++i) ASSERT_TRUE(fresh.frame(1.0 / 72, cmd)) << fresh.error();
    EXPECT_NEAR(fresh.time(), saved + 1.0, 1e-6);
    EXPECT_GT(fresh.level()->vm->field_float(kPlayer, fresh.level()->layout.fields.health), 0);
}

// The text follows Quake's layout line by line.
TEST_F(PlayedGame, TheTextHasQuakesLayout) {
    std::vector<std::string> lines;
    for (size_t start = 0, end; (end = text.find('\n', start)) != std::string::npos;
         start = end + 1) {
        lines.push_back(text.substr(start, end - start));
    }
    ASSERT_GT(lines.size(), 90u);
    EXPECT_EQ(lines[0], "5");
    EXPECT_EQ(lines[1].size(), kSaveCommentLength);
    EXPECT_EQ(lines[1].find(' '), std::string::npos);
    const int total =
        int(server.level()->vm->global_float(server.level()->layout.globals.total_monsters));
    char kills[32];
    std::snprintf(kills, sizeof kills, "kills:__2/%3i", total);
    std::replace(kills, kills + std::strlen(kills), ' ', '_');
    EXPECT_EQ(lines[1].substr(22), std::string(kills) + "____") << lines[1];
    EXPECT_EQ(lines[1].substr(0, 22), std::string(22, '_'));  // start has no title
    EXPECT_EQ(lines[2], "4097.000000");                       // parm1: IT_SHOTGUN | IT_AXE
    EXPECT_EQ(lines[18], "1");                                // skill
    EXPECT_EQ(lines[19], "start");
    EXPECT_EQ(lines[20].find('.'), lines[20].size() - 7);  // "%f" time
    EXPECT_EQ(lines[21], "m");                             // style 0 of start
    EXPECT_EQ(lines[85], "{");                             // the globals
    EXPECT_NE(text.find("\"v_forward_x\" \""), std::string::npos);
    EXPECT_EQ(text.find("\"v_forward\" \""), std::string::npos);  // vectors as their floats
    EXPECT_NE(text.find("\n{\n\"modelindex\" \"1.000000\"\n"), std::string::npos);  // world
    EXPECT_EQ(text.find("\"origin_x\""), std::string::npos);
    EXPECT_NE(text.find("\"classname\" \"player\"\n"), std::string::npos);
    EXPECT_NE(text.find("\n{\n}\n"), std::string::npos);  // a free edict
}

// A small but complete save of 'start' in QuakeSpasm's layout, written by hand: the world, the
// player standing near the start with a shotgun, the ogre standing (its enemy the player), a
// free edict and a health box. Indices and positions are those the real map gives.
constexpr const char* kQuakeSpasmSave = R"(5
LibreQuake:_Start_____kills:__0/_15____
4097.000000
100.000000
0.000000
25.000000
0.000000
0.000000
0.000000
2.000000
0.000000
0.000000
0.000000
0.000000
0.000000
0.000000
0.000000
0.000000
1
start
6.418025
m
mmnmmommommnonmmonqnmmo
abcdefghijklmnopqrstuvwxyzyxwvutsrqponmlkjihgfedcba
mmmmmaaaaammmmmaaaaaabcdefgabcdefg
mamamamamama
jklmnopqrstuvwxyzyxwvutsrqponmlkj
nmonqnmomnmomomno
mmmaaaabcdefgmmmmaaaammmaamm
mmmaaammmaaammmabcdefaaaammmmabcdefmmmaaaa
aaaaaaaazzzzzzzz
mmamammmmammamamaaamammma
abcdefghijklmnopqrrqponmlkjihgfedcba
m
m
m
m
m
m
m
m
m
m
m
m
m
m
m
m
m
m
m
m
m
m
m
m
m
m
m
m
m
m
m
m
m
m
m
m
m
m
m
m
m
m
m
m
m
m
m
m
m
m
m
a
{
"self" "0"
"other" "0"
"world" "0"
"time" "6.402778"
"frametime" "0.013889"
"force_retouch" "0.000000"
"mapname" "start"
"deathmatch" "0.000000"
"coop" "0.000000"
"teamplay" "0.000000"
"serverflags" "0.000000"
"total_secrets" "2.000000"
"total_monsters" "15.000000"
"found_secrets" "0.000000"
"killed_monsters" "0.000000"
"parm1" "4097.000000"
"parm2" "100.000000"
"v_forward_x" "0.000000"
"v_forward_y" "1.000000"
"v_forward_z" "0.000000"
"trace_fraction" "1.000000"
"trace_ent" "0"
"msg_entity" "1"
"framecount" "459.000000"
"skill" "1.000000"
"modelindex_eyes" "11.000000"
"modelindex_player" "10.000000"
"gameover" "0.000000"
"string_null" ""
"nextmap" ""
}
{
"modelindex" "1.000000"
"movetype" "7.000000"
"solid" "4.000000"
"classname" "worldspawn"
"model" "maps/start.bsp"
"message" "LibreQuake: Start"
"sounds" "2.000000"
"wad" "lq.wad"
}
{
"modelindex" "10.000000"
"absmin" "-177.000000 271.000000 -248.968750"
"absmax" "-143.000000 305.000000 -190.968750"
"movetype" "3.000000"
"solid" "3.000000"
"origin" "-160.000000 288.000000 -223.968750"
"angles" "0.000000 90.000000 0.000000"
"classname" "player"
"model" "progs/player.mdl"
"frame" "12.000000"
"mins" "-16.000000 -16.000000 -24.000000"
"maxs" "16.000000 16.000000 32.000000"
"size" "32.000000 32.000000 56.000000"
"think" "player_stand1"
"nextthink" "6.500000"
"health" "87.000000"
"weapon" "1.000000"
"weaponmodel" "progs/v_shot.mdl"
"currentammo" "25.000000"
"ammo_shells" "25.000000"
"items" "4097.000000"
"takedamage" "2.000000"
"view_ofs" "0.000000 0.000000 22.000000"
"v_angle" "0.000000 90.000000 0.000000"
"netname" "player"
"flags" "4616.000000"
"colormap" "1.000000"
"team" "1.000000"
"max_health" "100.000000"
"armortype" "0.300000"
"armorvalue" "15.000000"
"watertype" "-1.000000"
"th_pain" "player_pain"
"th_die" "PlayerDie"
"air_finished" "18.402779"
}
{
"modelindex" "74.000000"
"absmin" "135.000000 567.000000 -248.000000"
"absmax" "201.000000 633.000000 -158.000000"
"movetype" "4.000000"
"solid" "3.000000"
"origin" "168.000000 600.000000 -223.000000"
"angles" "0.000000 270.000000 0.000000"
"classname" "monster_ogre"
"model" "progs/ogre.mdl"
"frame" "4.000000"
"mins" "-32.000000 -32.000000 -24.000000"
"maxs" "32.000000 32.000000 64.000000"
"size" "64.000000 64.000000 88.000000"
"use" "monster_use"
"think" "ogre_stand5"
"nextthink" "6.500000"
"health" "200.000000"
"takedamage" "2.000000"
"view_ofs" "0.000000 0.000000 25.000000"
"enemy" "1"
"flags" "32.000000"
"ideal_yaw" "270.000000"
"yaw_speed" "20.000000"
"th_stand" "ogre_stand1"
"th_walk" "ogre_walk1"
"th_run" "ogre_run1"
"th_missile" "ogre_nail1"
"th_melee" "ogre_melee"
"th_pain" "ogre_pain"
"th_die" "ogre_die"
"pausetime" "100000000.000000"
}
{
}
{
"modelindex" "41.000000"
"absmin" "177.000000 17.000000 -247.968750"
"absmax" "239.000000 79.000000 -191.968750"
"movetype" "6.000000"
"solid" "1.000000"
"origin" "192.000000 32.000000 -247.968750"
"classname" "item_health"
"model" "maps/b_bh25.bsp"
"maxs" "32.000000 32.000000 56.000000"
"size" "32.000000 32.000000 56.000000"
"touch" "health_touch"
"flags" "768.000000"
"noise" "items/health1.wav"
"mdl" "maps/b_bh25.bsp"
"healamount" "25.000000"
"healtype" "1.000000"
}
)";

TEST(QuakeSpasmSave, LoadsAndRuns) {
    TestHost host;
    auto game = read_savegame(kQuakeSpasmSave, "qs.sav");
    ASSERT_TRUE(game) << game.error().to_string();
    EXPECT_EQ(game->comment, "LibreQuake:_Start_____kills:__0/_15____");
    EXPECT_EQ(game->map, "start");
    EXPECT_EQ(game->skill, 1);
    EXPECT_EQ(game->spawn_parms[0], 4097);
    EXPECT_EQ(game->lightstyles[63], "a");
    ASSERT_EQ(game->edicts.size(), 5u);
    EXPECT_TRUE(game->edicts[3].pairs.empty());

    Server server(host);
    const SpawnResult result = server.load_game(*game, {});
    ASSERT_TRUE(result.error.empty()) << result.error;
    ServerLevel& level = *server.level();
    const FieldOffsets& f = level.layout.fields;
    EXPECT_DOUBLE_EQ(server.time(), 6.418025);
    EXPECT_EQ(level.vm->num_edicts(), 5u);
    EXPECT_EQ(level.vm->field_float(kPlayer, f.health), 87);
    EXPECT_EQ(level.vm->field_float(kPlayer, f.armorvalue), 15);
    EXPECT_EQ(level.vm->field_vector(kPlayer, f.origin), (vm::Vec3f{-160, 288, -223.96875f}));
    EXPECT_EQ(function_name(level, 2, f.think), "ogre_stand5");
    EXPECT_EQ(enemy_of(level, 2), kPlayer);
    EXPECT_TRUE(level.edicts.is_free(3));
    EXPECT_EQ(function_name(level, 4, f.touch), "health_touch");
    EXPECT_EQ(level.lightstyles[1], "mmnmmommommnonmmonqnmmo");
    EXPECT_EQ(level.vm->global_float(level.layout.globals.total_secrets), 2);
    EXPECT_EQ(level.client.spawn_parms[7], 2);
    EXPECT_TRUE(level.world.linked(2));
    // The comment our writer makes for this level is the one QuakeSpasm made.
    EXPECT_EQ(savegame_comment(level), "LibreQuake: Start     kills:  0/ 15    ");
    for (int i = 0; i < 72; ++i) ASSERT_TRUE(server.frame(1.0 / 72, {})) << server.error();
}

// ---- malformed saves

std::string read_error(const std::string& text) {
    auto game = read_savegame(text, "bad.sav");
    return game ? "" : game.error().to_string();
}

TEST(SavegameErrors, WrongVersion) {
    test::SynthSav s = test::minimal_sav();
    s.version = "6";
    EXPECT_EQ(read_error(test::write_sav(s)),
              "bad.sav: offset 0: version 6: only version 5 (id Quake, QuakeSpasm) is read");
    s.version = "five";
    EXPECT_NE(read_error(test::write_sav(s)).find("offset 0: the version 'five' is not a number"),
              std::string::npos);
}

TEST(SavegameErrors, TruncatedAnywhere) {
    const std::string text = test::write_sav(test::minimal_sav());
    ASSERT_EQ(read_error(text), "");
    for (size_t size = 0; size + 1 < text.size(); size += 7) {
        const std::string error = read_error(text.substr(0, size));
        EXPECT_EQ(error.rfind("bad.sav: offset ", 0), 0u) << size << ": " << error;
        EXPECT_NE(error.find("truncated"), std::string::npos) << size << ": " << error;
    }
}

TEST(SavegameErrors, BadNumbers) {
    test::SynthSav s = test::minimal_sav();
    s.parms[3] = "2x5";
    const std::string text = test::write_sav(s);
    EXPECT_EQ(read_error(text), "bad.sav: offset " + std::to_string(text.find("2x5")) +
                                    ": a spawn parm '2x5' is not a number");
    s = test::minimal_sav();
    s.time = "-4";
    EXPECT_NE(read_error(test::write_sav(s)).find("the server time -4 is out of range"),
              std::string::npos);
    s = test::minimal_sav();
    s.skill = "nan";
    EXPECT_NE(read_error(test::write_sav(s)).find("the skill is not a finite number"),
              std::string::npos);
    s = test::minimal_sav();
    s.parms[0] = "1e99";
    EXPECT_NE(read_error(test::write_sav(s)).find("out of range"), std::string::npos);
}

TEST(SavegameErrors, HugeStringsAndBrokenBlocks) {
    test::SynthSav s = test::minimal_sav();
    s.edicts[1].push_back({"message", std::string(5000, 'x')});
    std::string text = test::write_sav(s);
    EXPECT_EQ(read_error(text), "bad.sav: offset " + std::to_string(text.find("\"xxx")) +
                                    ": a token longer than 1023 bytes");
    s = test::minimal_sav();
    s.lightstyles.resize(6, "m");
    s.lightstyles[5] = std::string(2000, 'a');
    EXPECT_NE(read_error(test::write_sav(s)).find("a light style is longer than 1023 bytes"),
              std::string::npos);
    s = test::minimal_sav();
    s.trailing = "{\n\"classname\" }\n";
    text = test::write_sav(s);
    EXPECT_EQ(read_error(text), "bad.sav: offset " + std::to_string(text.size() - 2) +
                                    ": 'classname' has no value before the brace");
    s.trailing = "\"stray\"\n";
    EXPECT_NE(read_error(test::write_sav(s)).find("expected '{', found 'stray'"),
              std::string::npos);
    s.trailing = "{\n\"message\" \"no end\n}\n";
    EXPECT_NE(read_error(test::write_sav(s)).find("string without a closing quote"),
              std::string::npos);
    EXPECT_NE(read_error(std::string("5\0", 2)).find("offset 1: NUL byte"), std::string::npos);
}

TEST(SavegameErrors, UnknownMapAndUnknownFunction) {
    TestHost host;
    test::SynthSav s = test::minimal_sav();
    s.map = "nosuchmap";
    std::string text = test::write_sav(s);
    auto game = read_savegame(text, "bad.sav");
    ASSERT_TRUE(game) << game.error().to_string();
    Server server(host);
    SpawnResult result = server.load_game(*game, {});
    EXPECT_EQ(result.error, "bad.sav: offset " + std::to_string(text.find("nosuchmap")) +
                                ": cannot find maps/nosuchmap.bsp");
    EXPECT_FALSE(server.active());

    s = test::minimal_sav();
    s.edicts[1].push_back({"think", "no_such_function"});
    text = test::write_sav(s);
    game = read_savegame(text, "bad.sav");
    ASSERT_TRUE(game) << game.error().to_string();
    result = server.load_game(*game, {});
    EXPECT_EQ(result.error, "bad.sav: offset " + std::to_string(text.rfind("\"think\"")) +
                                ": edict 1: 'think' names no function 'no_such_function' of "
                                "progs.dat");
    EXPECT_FALSE(server.active());

    s = test::minimal_sav();
    s.map = "../start";
    EXPECT_NE(read_error(test::write_sav(s)).find("'../start' is not a map name"),
              std::string::npos);
}

TEST(SavegameErrors, SynthSeedsParse) {
    for (const test::SeedFile& seed : test::synthetic_sav_seeds()) {
        SCOPED_TRACE(seed.name);
        const std::string text(seed.bytes.begin(), seed.bytes.end());
        const bool valid = seed.name.find("version") == std::string::npos &&
                           seed.name.find("truncated") == std::string::npos &&
                           seed.name.find("bad_") == std::string::npos;
        EXPECT_EQ(read_error(text).empty(), valid) << read_error(text);
    }
}

}  // namespace
}  // namespace nq::server

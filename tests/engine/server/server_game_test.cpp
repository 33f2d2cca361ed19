// The game server on real LibreQuake data: levels spawn what their entity lumps list (minus the
// skill's exclusions), the client's messages decode with the demo decoder into a signed-on
// client stream, frames advance time and keep the player out of solid, and a hostile progs ends
// the level with a clear error instead of crashing.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <map>

#include "common/file_io.h"
#include "formats/bsp.h"
#include "formats/entities.h"
#include "formats/message_decoder.h"
#include "server/progs_layout.h"
#include "server/server.h"
#include "server/server_level.h"
#include "support/data_server_host.h"
#include "support/synth_progs.h"
#include "support/test_data.h"

namespace nq::server {
namespace {

using TestHost = test::DataServerHost;

constexpr int kNotEasy = 256, kNotMedium = 512, kNotHard = 1024;

// Classnames of the lump's entities that skill 1 keeps, counted (computed from the raw lump).
std::map<std::string, int> expected_classes(const std::string& map) {
    const std::string path = test::lq1_dir() + "/maps/" + map + ".bsp";
    auto bytes = nq::read_file(path);
    auto bsp = parse_bsp(*bytes, path);
    auto entities = parse_entities(bsp->entities, path);
    std::map<std::string, int> counts;
    for (const Entity& e : entities->entities) {
        const int flags = int(
            std::strtof(std::string(find_value(e, "spawnflags").value_or("0")).c_str(), nullptr));
        if (flags & kNotMedium) continue;
        ++counts[std::string(classname(e))];
    }
    (void)kNotEasy;
    (void)kNotHard;
    return counts;
}

std::map<std::string, int> live_classes(ServerLevel& level) {
    std::map<std::string, int> counts;
    for (uint32_t e = 0; e < level.vm->num_edicts(); ++e) {
        if (level.edicts.is_free(e)) continue;
        ++counts[std::string(
            level.vm->string_or_empty(level.vm->field_int(e, level.layout.fields.classname)))];
    }
    return counts;
}

std::vector<DecodedMessage> decode_all(const Server& server, protocol::ProtocolState& state) {
    std::vector<DecodedMessage> all;
    for (const std::vector<uint8_t>& block : server.client_messages()) {
        auto decoded = decode_server_message(block, {"server", 0, 0}, state);
        EXPECT_TRUE(decoded) << decoded.error().to_string();
        if (!decoded) break;
        for (DecodedMessage& m : decoded->messages) all.push_back(std::move(m));
    }
    return all;
}

TEST(ServerGame, EveryLevelSpawnsWhatItsLumpLists) {
    for (const char* map : {"start", "e2m3", "lq1m1"}) {
        SCOPED_TRACE(map);
        TestHost host;
        Server server(host);
        const SpawnResult result = server.spawn(map, {});
        ASSERT_TRUE(result.error.empty()) << result.error << host.console;
        const std::map<std::string, int> expected = expected_classes(map);
        const std::map<std::string, int> live = live_classes(*server.level());
        int monsters = 0;
        for (const auto& [name, count] : expected) {
            // Monsters, items and weapons stay as spawned (lights and path corners may remove
            // themselves, as QuakeC decides).
            if (name.rfind("monster_", 0) == 0 || name.rfind("item_", 0) == 0 ||
                name.rfind("weapon_", 0) == 0) {
                EXPECT_EQ(live.count(name) ? live.at(name) : 0, count) << name;
            }
            if (name.rfind("monster_", 0) == 0) monsters += count;
            // id's fish.qc counts every fish twice (monster_fish and swimmonster_start both
            // add one); LibreQuake kept it, and QuakeSpasm's scoreboard shows the same total.
            if (name == "monster_fish") monsters += count;
        }
        ServerLevel& level = *server.level();
        EXPECT_EQ(level.vm->global_float(level.layout.globals.total_monsters), float(monsters));
        EXPECT_EQ(live.at("worldspawn"), 1);
        EXPECT_EQ(live.at("player"), 1);  // PutClientInServer made edict 1 the player
    }
}

TEST(ServerGame, SignonDecodesAsAClientStream) {
    TestHost host;
    Server server(host);
    ASSERT_TRUE(server.spawn("start", {}).error.empty()) << host.console;
    protocol::ProtocolState state;
    const std::vector<DecodedMessage> messages = decode_all(server, state);
    EXPECT_EQ(state.protocol, protocol::kFitzQuake);
    std::vector<int> signons;
    const svc::ServerInfo* info = nullptr;
    int baselines = 0;
    for (const DecodedMessage& m : messages) {
        if (auto* s = std::get_if<svc::SignonNum>(&m.message)) signons.push_back(s->stage);
        if (auto* s = std::get_if<svc::ServerInfo>(&m.message)) info = s;
        if (std::holds_alternative<svc::SpawnBaseline>(m.message) ||
            std::holds_alternative<svc::SpawnBaseline2>(m.message)) {
            ++baselines;
        }
    }
    EXPECT_EQ(signons, (std::vector<int>{1, 2, 3}));
    ASSERT_NE(info, nullptr);
    ASSERT_FALSE(info->models.empty());
    EXPECT_EQ(info->models[0], "maps/start.bsp");
    const ServerLevel& level = *server.level();
    EXPECT_EQ(info->models.size() + 1, level.model_names.size());
    EXPECT_EQ(info->sounds.size() + 1, level.sound_names.size());
    EXPECT_GT(baselines, 10);

    // Frames: each starts with the server time, which advances by the frame time.
    for (int i = 0; i < 20; ++i) {
        ASSERT_TRUE(server.frame(1.0 / 72, {})) << server.error();
        const std::vector<DecodedMessage> frame = decode_all(server, state);
        ASSERT_FALSE(frame.empty());
        const auto* time = std::get_if<svc::Time>(&frame[0].message);
        ASSERT_NE(time, nullptr);
        EXPECT_NEAR(time->time, 1.0 + 0.2 + (i + 1) / 72.0, 1e-3);
        int player_updates = 0;
        for (const DecodedMessage& m : frame) {
            if (auto* u = std::get_if<svc::EntityUpdate>(&m.message))
                player_updates += u->entity == 1;
        }
        EXPECT_EQ(player_updates, 1);
    }
}

TEST(ServerGame, StandingPlayerStaysOnTheFloorOutOfSolid) {
    TestHost host;
    Server server(host);
    ASSERT_TRUE(server.spawn("start", {}).error.empty()) << host.console;
    for (int i = 0; i < 144; ++i) ASSERT_TRUE(server.frame(1.0 / 72, {})) << server.error();
    ServerLevel& level = *server.level();
    const vm::Vec3f origin = level.vm->field_vector(1, level.layout.fields.origin);
    EXPECT_NE(point_contents(*level.bsp, 0, origin), bsp_contents::solid);
    EXPECT_TRUE(int(level.vm->field_float(1, level.layout.fields.flags)) & qc::kFlOnGround);
}

TEST(ServerGame, BrokenProgsEndsTheLevelWithAClearError) {
    // The real progs with its first `main`-like function's code replaced by a runaway loop.
    TestHost host;
    auto bytes = nq::read_file(test::lq1_dir() + "/progs.dat");
    ASSERT_TRUE(bytes);
    auto progs = vm::parse_progs(*bytes, "progs.dat");
    ASSERT_TRUE(progs);
    const int32_t worldspawn = progs->find_function("worldspawn");
    ASSERT_GT(worldspawn, 0);
    int32_t ofs_statements;
    std::memcpy(&ofs_statements, bytes->data() + 8, 4);
    const int32_t first = progs->functions[size_t(worldspawn)].first_statement;
    // GOTO 0: jumps to itself forever.
    uint8_t* at = bytes->data() + ofs_statements + first * 8;
    const uint16_t goto_self[4] = {61, 0, 0, 0};
    std::memcpy(at, goto_self, 8);
    host.overrides["progs.dat"] = *bytes;
    Server server(host);
    const SpawnResult result = server.spawn("start", {});
    EXPECT_NE(result.error.find("runaway loop"), std::string::npos) << result.error;
    EXPECT_NE(result.error.find("worldspawn"), std::string::npos) << result.error;
    EXPECT_FALSE(server.active());

    host.overrides["progs.dat"] = {1, 2, 3};
    EXPECT_NE(server.spawn("start", {}).error.find("progs.dat"), std::string::npos);
    host.overrides.erase("progs.dat");
    EXPECT_NE(server.spawn("nosuchmap", {}).error.find("maps/nosuchmap.bsp"), std::string::npos);
}

}  // namespace
}  // namespace nq::server

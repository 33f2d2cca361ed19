// Playing the real LibreQuake demos through DemoPlayer + ClientState: timedemo frame pacing
// against an independent count, playback at recorded speed, the map restart in demo2.dem,
// and entity positions against what the map and the messages say.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <regex>
#include <string>
#include <variant>
#include <vector>

#include "client/demo_player.h"
#include "client/view.h"
#include "client/visible_entities.h"
#include "client_test_fixture.h"
#include "formats/demo_summary.h"

namespace nq {
namespace {

constexpr double kFrameTime = 1.0 / 72;

const DecodedDemo& decoded(const std::string& file) {
    static std::map<std::string, DecodedDemo> cache;
    auto it = cache.find(file);
    if (it != cache.end()) return it->second;
    auto d = decode_demo(test::load_lq1(file), file);
    if (!d) throw std::runtime_error(d.error().to_string());
    return cache.emplace(file, std::move(d.value())).first->second;
}

// Independent pacing model, from the rules Quake's client follows: blocks are read all at once
// until signed on (stage 3 plus the first entity update), then one per frame; a new
// serverinfo starts the connection again; the frame that meets svc_disconnect (or the end of
// the file) is not played. Every frame played reads exactly one block that starts signed on.
struct ExpectedPacing {
    size_t frames = 0;
    size_t blocks_before_first_signon = 0;
    size_t serverinfos = 0;
};
ExpectedPacing expected_pacing(const DecodedDemo& demo) {
    ExpectedPacing out;
    int signon = 0;
    bool ever_signed_on = false;
    for (const DecodedBlock& block : demo.blocks) {
        const bool starts_signed_on = signon == 4;
        if (!ever_signed_on) ++out.blocks_before_first_signon;
        bool disconnect = false;
        for (const DecodedMessage& m : block.messages) {
            const ServerMessage& msg = m.message;
            if (std::holds_alternative<svc::ServerInfo>(msg)) {
                signon = 0;
                ++out.serverinfos;
            } else if (auto* s = std::get_if<svc::SignonNum>(&msg)) {
                signon = s->stage;
            } else if (std::holds_alternative<svc::EntityUpdate>(msg) && signon == 3) {
                signon = 4;
                ever_signed_on = true;
            } else if (std::holds_alternative<svc::Disconnect>(msg)) {
                disconnect = true;
                break;
            }
        }
        if (disconnect) break;
        if (starts_signed_on) ++out.frames;
    }
    return out;
}

class RealDemoPlay : public ::testing::TestWithParam<const char*> {};

TEST_P(RealDemoPlay, TimedemoConsumesEveryBlockOnePerFrame) {
    const std::string file = GetParam();
    auto player = DemoPlayer::open(test::load_lq1(file), file, DemoMode::TimeDemo);
    ASSERT_TRUE(player.ok()) << player.error().to_string();
    ClientState client;
    uint32_t generation = 0;
    std::vector<uint32_t> generations_seen;
    size_t previous_blocks = 0;
    size_t frames_reading_one_block = 0, max_particles = 0;
    while (player->run_frame(client, kFrameTime) == FrameStatus::Playing) {
        if (client.generation() != generation) {
            generation = client.generation();
            generations_seen.push_back(generation);
            client.set_model_info(test::load_model_info(client.model_names()));
        }
        ASSERT_TRUE(client.signed_on());
        // In timedemo the clock is the server time of the block just read.
        EXPECT_EQ(client.time(), client.message_time(0));
        if (player->blocks_read() - previous_blocks == 1) ++frames_reading_one_block;
        previous_blocks = player->blocks_read();
        max_particles = std::max(max_particles, client.particles().size());
    }
    EXPECT_FALSE(player->error().has_value()) << player->error()->to_string();
    EXPECT_EQ(player->blocks_read(), player->block_count());
    EXPECT_EQ(player->block_count(), decoded(file).blocks.size());
    EXPECT_TRUE(client.disconnected());
    EXPECT_TRUE(client.warnings().empty()) << client.warnings().front();

    const ExpectedPacing expected = expected_pacing(decoded(file));
    EXPECT_EQ(player->frames(), expected.frames);
    EXPECT_EQ(player->timedemo_frames(), expected.frames - 1);
    // Only the first frame (and one after a map restart) reads several blocks.
    EXPECT_EQ(frames_reading_one_block, player->frames() - expected.serverinfos);
    // Each serverinfo is one generation, seen in order.
    std::vector<uint32_t> want;
    for (uint32_t g = 1; g <= expected.serverinfos; ++g) want.push_back(g);
    EXPECT_EQ(generations_seen, want);
    EXPECT_LE(max_particles, client.particles().capacity());
    EXPECT_GT(max_particles, 0u);
}

TEST(RealDemoPlay, DemoDotDemFrameCountsMatchItsLayout) {
    // demo.dem: blocks 0-3 carry the connection (block 3 holds the first entity update), the
    // last block is a lone svc_disconnect. The first frame reads blocks 0-4, each later frame
    // one block up to 1724; reading block 1725 ends playback. Quake's timedemo would report
    // (frame reading 1725 = 1721) - 1 = 1720 frames.
    auto player = DemoPlayer::open(test::load_lq1("demo.dem"), "demo.dem", DemoMode::TimeDemo);
    ASSERT_TRUE(player.ok());
    ClientState client;
    while (player->run_frame(client, 0.001) == FrameStatus::Playing) {
    }
    EXPECT_EQ(player->block_count(), 1726u);
    EXPECT_EQ(expected_pacing(decoded("demo.dem")).blocks_before_first_signon, 4u);
    EXPECT_EQ(player->frames(), 1721u);  // one per block 4..1724
    EXPECT_EQ(player->timedemo_frames(), 1720u);
}

TEST_P(RealDemoPlay, PlaybackRunsAtRecordedSpeed) {
    const std::string file = GetParam();
    auto player = DemoPlayer::open(test::load_lq1(file), file, DemoMode::Playback);
    ASSERT_TRUE(player.ok());
    ClientState client;
    size_t frames = 0;
    while (player->run_frame(client, kFrameTime) == FrameStatus::Playing) {
        ++frames;
        ASSERT_GE(client.lerp_fraction(), 0.0f);
        ASSERT_LE(client.lerp_fraction(), 1.0f);
        // The clock stays between the two latest server times (within Quake's 1% slack).
        if (client.message_time(0) > client.message_time(1)) {
            EXPECT_GE(client.time(), client.message_time(1) - 1e-9);
            EXPECT_LE(client.time(), client.message_time(0) + 0.011);
        }
    }
    EXPECT_FALSE(player->error().has_value());
    EXPECT_EQ(player->blocks_read(), player->block_count());
    // Played at 72 frames per second, the demo lasts about its recorded time.
    DemoSummary s = summarize_demo(decoded(file), file);
    const double played = static_cast<double>(frames) * kFrameTime;
    // Each map segment starts 0.1 s before its first server time (the clock is pulled to the
    // start of the first interval) and ends a frame late.
    const double slack = static_cast<double>(s.maps.size()) * (0.1 + 2 * kFrameTime);
    EXPECT_NEAR(played, s.playback_time, slack);
}

// What maps/start.bsp places, read with a few lines of independent code: the entities lump.
std::string start_map_entities() {
    std::vector<uint8_t> bsp = test::load_lq1("maps/start.bsp");
    auto le32 = [&](size_t at) {
        return static_cast<int32_t>(bsp[at] | (bsp[at + 1] << 8) | (bsp[at + 2] << 16) |
                                    (static_cast<uint32_t>(bsp[at + 3]) << 24));
    };
    const size_t lump = 4;  // directory entry 0 (entities): offset, length
    return std::string(reinterpret_cast<const char*>(bsp.data()) + le32(lump),
                       static_cast<size_t>(le32(lump + 4)));
}
Vec3 map_origin_of(const std::string& entities, const std::string& classname) {
    std::smatch block, origin;
    std::regex block_re("\\{[^}]*\"classname\" \"" + classname + "\"[^}]*\\}");
    if (!std::regex_search(entities, block, block_re)) throw std::runtime_error(classname);
    std::string text = block.str();
    std::regex origin_re("\"origin\" \"(-?[0-9.]+) (-?[0-9.]+) (-?[0-9.]+)\"");
    if (!std::regex_search(text, origin, origin_re)) throw std::runtime_error("origin");
    return {std::stof(origin[1]), std::stof(origin[2]), std::stof(origin[3])};
}

TEST_P(RealDemoPlay, ExploboxStandsWhereTheMapPutsIt) {
    const std::string file = GetParam();
    const Vec3 expected = map_origin_of(start_map_entities(), "misc_explobox2");
    auto player = DemoPlayer::open(test::load_lq1(file), file, DemoMode::Playback);
    ASSERT_TRUE(player.ok());
    ClientState client;
    size_t frames_seen = 0;
    while (player->run_frame(client, kFrameTime) == FrameStatus::Playing) {
        const auto& names = client.model_names();
        auto it = std::find(names.begin(), names.end(), "maps/b_exbox2.bsp");
        ASSERT_NE(it, names.end());
        const int model = static_cast<int>(it - names.begin());
        for (size_t i = 1; i < client.entity_slots(); ++i) {
            const ClientEntity& e = *client.entity(static_cast<int>(i));
            if (!e.visible || e.model != model) continue;
            EXPECT_EQ(e.origin, expected) << "entity " << i << " at " << client.time();
            ++frames_seen;
        }
    }
    EXPECT_GT(frames_seen, 10u);
}

// The player's origin after every timedemo frame equals what the messages read so far say:
// the latest update's coordinates, the baseline's where the update sent none.
TEST_P(RealDemoPlay, PlayerOriginFollowsTheMessages) {
    const std::string file = GetParam();
    const DecodedDemo& demo = decoded(file);
    auto player = DemoPlayer::open(test::load_lq1(file), file, DemoMode::TimeDemo);
    ASSERT_TRUE(player.ok());
    ClientState client;
    Vec3 base{}, latest{};
    size_t walked = 0, checked = 0;
    const uint32_t axis_bits[3] = {protocol::U_ORIGIN1, protocol::U_ORIGIN2, protocol::U_ORIGIN3};
    while (player->run_frame(client, kFrameTime) == FrameStatus::Playing) {
        for (; walked < player->blocks_read(); ++walked) {
            for (const DecodedMessage& m : demo.blocks[walked].messages) {
                if (auto* b = std::get_if<svc::SpawnBaseline>(&m.message); b && b->entity == 1) {
                    base = b->state.origin;
                }
                if (auto* u = std::get_if<svc::EntityUpdate>(&m.message); u && u->entity == 1) {
                    for (int i = 0; i < 3; ++i)
                        latest[i] = u->has(axis_bits[i]) ? u->origin[i] : base[i];
                }
            }
        }
        ASSERT_EQ(client.view_entity(), 1);
        const ClientEntity* e = client.entity(1);
        ASSERT_NE(e, nullptr);
        if (!e->visible) continue;
        ASSERT_EQ(e->origin, latest) << "frame " << player->frames() << " time " << client.time();
        ++checked;
    }
    EXPECT_GT(checked, 1000u);
}

TEST(RealDemoPlay, MapRestartInDemo2StartsAFreshGeneration) {
    auto player = DemoPlayer::open(test::load_lq1("demo2.dem"), "demo2.dem", DemoMode::TimeDemo);
    ASSERT_TRUE(player.ok());
    ClientState client;
    double last_time_of_first_map = 0;
    int frags_before = 0;
    bool restarted = false;
    while (player->run_frame(client, kFrameTime) == FrameStatus::Playing) {
        if (client.generation() == 1) {
            last_time_of_first_map = client.time();
            frags_before = client.scoreboard()[0].frags;
            continue;
        }
        if (restarted) continue;
        restarted = true;
        EXPECT_EQ(client.generation(), 2u);
        EXPECT_TRUE(client.signed_on());
        EXPECT_EQ(client.model_names()[1], "maps/start.bsp");
        EXPECT_LT(client.time(), last_time_of_first_map);  // the server clock restarted
        EXPECT_EQ(frags_before, -2);  // "player commited suicide" twice before the restart
        EXPECT_EQ(client.scoreboard()[0].frags, 0);
        EXPECT_EQ(client.intermission(), Intermission::None);
        // Entities of the old map are gone: only those the new map's messages mention exist.
        for (size_t i = 1; i < client.entity_slots(); ++i) {
            const ClientEntity& e = *client.entity(static_cast<int>(i));
            EXPECT_TRUE(e.msg_time < 0 || e.msg_time <= client.message_time(0)) << i;
        }
    }
    EXPECT_TRUE(restarted);
    EXPECT_EQ(client.generation(), 2u);
}

// Real TE_EXPLOSION messages in demo2.dem leave their particles and a light.
TEST(RealDemoPlay, RealExplosionsSpawnParticlesAndLight) {
    const DecodedDemo& demo = decoded("demo2.dem");
    size_t explosion_block = 0;
    Vec3 where{};
    for (size_t b = 0; b < demo.blocks.size() && explosion_block == 0; ++b) {
        for (const DecodedMessage& m : demo.blocks[b].messages) {
            auto* t = std::get_if<svc::TempEntity>(&m.message);
            if (t && t->type == protocol::TE_EXPLOSION) {
                explosion_block = b;
                where = t->origin;
            }
        }
    }
    ASSERT_GT(explosion_block, 0u);
    auto player = DemoPlayer::open(test::load_lq1("demo2.dem"), "demo2.dem", DemoMode::TimeDemo);
    ClientState client;
    while (player->blocks_read() <= explosion_block) {
        ASSERT_EQ(player->run_frame(client, kFrameTime), FrameStatus::Playing);
    }
    EXPECT_GE(client.particles().size(), static_cast<size_t>(kExplosionParticles));
    bool light = false;
    for (const DynamicLight& l : client.dynamic_lights().all()) {
        if (l.lit(client.time()) && l.origin == where && l.radius <= 350 && l.radius > 300)
            light = true;
    }
    EXPECT_TRUE(light);
}

INSTANTIATE_TEST_SUITE_P(Lq1, RealDemoPlay, ::testing::Values("demo.dem", "demo2.dem"));

}  // namespace
}  // namespace nq

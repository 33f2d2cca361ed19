// Bad demos: messages the client refuses end playback with an error naming the file, the
// absolute offset of the message and the problem; randomly corrupted real demo blocks never
// crash or hang the player (this binary runs under ASan + UBSan in the sanitizer build).
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "client/demo_player.h"
#include "client/view.h"
#include "client/visible_entities.h"
#include "client_test_fixture.h"
#include "formats/message_encoder.h"
#include "support/raw_bytes.h"
#include "support/synth_dem.h"

namespace nq {
namespace {

using test::read_le32;

using namespace protocol;
using Bytes = std::vector<uint8_t>;

// Plays `file` to its end in timedemo mode (bounded), returning the player.
DemoPlayer play(const Bytes& file, DemoMode mode = DemoMode::TimeDemo, size_t max_frames = 100000) {
    auto player = DemoPlayer::open(file, "bad.dem", mode);
    if (!player) throw std::runtime_error(player.error().to_string());
    ClientState client;
    VisibleEntityList list(256);
    ViewState view;
    for (size_t i = 0; i < max_frames; ++i) {
        if (player->run_frame(client, 1.0 / 72) == FrameStatus::Ended) break;
        collect_visible_entities(client, compute_view(client, view), list);
    }
    return std::move(player.value());
}

svc::ServerInfo info() {
    svc::ServerInfo i = test::server_info({"maps/x.bsp", "progs/a.mdl"});
    return i;
}

TEST(ClientErrors, ModelIndexBeyondThePrecacheEndsPlaybackAtTheMessage) {
    svc::EntityUpdate bad = test::origin_update(1, {0, 0, 0});
    bad.bits |= U_MODEL;
    bad.model = 7;  // only 2 models precached
    Bytes file = test::build_demo({{info()}, {svc::Time{1.0f}, bad}});
    DemoPlayer player = play(file);
    ASSERT_TRUE(player.error().has_value());
    const Error& e = *player.error();
    // Independent offset: "-1\n", block 0's header and message, block 1's header, svc_time.
    const size_t block1 = 3 + 16 + static_cast<size_t>(read_le32(file, 3));
    EXPECT_EQ(e.offset, block1 + 16 + 5);
    EXPECT_EQ(e.file, "bad.dem");
    EXPECT_NE(e.message.find("block 1"), std::string::npos) << e.message;
    EXPECT_NE(e.message.find("model index 7"), std::string::npos) << e.message;
    EXPECT_EQ(player.blocks_read(), 2u);
}

TEST(ClientErrors, ScoreboardSlotOutsideMaxClients) {
    svc::UpdateFrags frags;
    frags.client = 3;  // max_clients is 1
    DemoPlayer player = play(test::build_demo({{info(), frags}}));
    ASSERT_TRUE(player.error().has_value());
    EXPECT_NE(player.error()->message.find("svc_updatefrags: client 3 outside 0..0"),
              std::string::npos)
        << player.error()->message;
}

TEST(ClientErrors, RefusedMessagesLeaveTheStateAlone) {
    ClientState client;
    test::apply_all(client, {info(), test::baseline(4, 2, {1, 1, 1})});
    svc::SpawnBaseline bad = test::baseline(4, 9, {2, 2, 2});
    EXPECT_TRUE(client.apply(bad).has_value());
    EXPECT_EQ(client.entity(4)->baseline.origin, (Vec3{1, 1, 1}));
    svc::ServerInfo too_many = info();
    too_many.max_clients = 17;
    EXPECT_TRUE(client.apply(too_many).has_value());
    EXPECT_EQ(client.generation(), 1u);
    svc::SpawnStatic s;
    s.state.model = 3;
    EXPECT_TRUE(client.apply(s).has_value());
    EXPECT_TRUE(client.static_entities().empty());
    svc::UpdateStat stat;
    stat.stat = 32;
    EXPECT_TRUE(client.apply(stat).has_value());
}

TEST(ClientErrors, DecoderErrorsEndPlaybackToo) {
    Bytes file = test::build_raw_demo({{static_cast<uint8_t>(svc_time), 0, 0}});  // cut float
    DemoPlayer player = play(file);
    ASSERT_TRUE(player.error().has_value());
    EXPECT_EQ(player.blocks_read(), 1u);
}

TEST(ClientErrors, EmptyDemoEndsAtOnce) {
    DemoPlayer player = play(test::build_demo({}));
    EXPECT_FALSE(player.error().has_value());
    EXPECT_TRUE(player.ended());
    EXPECT_EQ(player.frames(), 0u);
    EXPECT_EQ(player.timedemo_frames(), 0u);
}

// A small deterministic mutator: flips, overwrites and duplicates bytes of message bodies
// (the container stays valid so the client sees the damage).
class Mutator {
  public:
    explicit Mutator(uint64_t seed) : random_(seed) {}
    Demo mutate(Demo demo) {
        const int edits = 1 + random_.rand15() % 8;
        for (int i = 0; i < edits; ++i) {
            DemoBlock& b = demo.blocks[static_cast<size_t>(random_.rand15()) % demo.blocks.size()];
            if (b.message.empty()) continue;
            size_t at = static_cast<size_t>(random_.rand15()) % b.message.size();
            switch (random_.rand15() % 4) {
                case 0:
                    b.message[at] ^= static_cast<uint8_t>(1u << (random_.rand15() % 8));
                    break;
                case 1:
                    b.message[at] = static_cast<uint8_t>(random_.rand15());
                    break;
                case 2:
                    b.message[at] = 0xFF;
                    break;
                default:
                    b.message.insert(b.message.begin() + static_cast<ptrdiff_t>(at),
                                     b.message.begin() + static_cast<ptrdiff_t>(at),
                                     b.message.begin() + static_cast<ptrdiff_t>(
                                                             std::min(b.message.size(), at + 7)));
            }
        }
        return demo;
    }

  private:
    ClientRandom random_;
};

TEST(ClientRobustness, CorruptedRealDemosNeverCrash) {
    auto parsed = parse_dem(test::load_lq1("demo2.dem"), "demo2.dem");
    ASSERT_TRUE(parsed.ok());
    Demo head = parsed.value();
    head.blocks.resize(80);  // the connection and ~70 frames: quick to play many times
    Mutator mutator(2024);
    size_t errors = 0, clean = 0;
    for (int round = 0; round < 300; ++round) {
        Bytes file = write_dem(mutator.mutate(head));
        for (DemoMode mode : {DemoMode::TimeDemo, DemoMode::Playback}) {
            DemoPlayer player = play(file, mode, 2000);
            if (player.error()) {
                ++errors;
                EXPECT_LE(player.error()->offset, file.size());
                EXPECT_EQ(player.error()->file, "bad.dem");
            } else {
                ++clean;
            }
        }
    }
    EXPECT_GT(errors, 0u);  // the corruption does reach the client
    EXPECT_GT(clean, 0u);
}

}  // namespace
}  // namespace nq

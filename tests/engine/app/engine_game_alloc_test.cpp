// The game's frame allocates nothing once warm: on e2m3 with its monsters woken and hunting the
// god-mode player (projectiles, pain, deaths of monsters in crossfire), every frame's server
// work — client command, physics, QuakeC, messages — and the client's part of it — decoding and
// applying the messages, interpolation and effects — runs without a heap allocation.
#include <gtest/gtest.h>

#include "app/sessions/live_game.h"
#include "common/file_io.h"
#include "server/monster_waking.h"
#include "server/server_commands.h"
#include "server/server_level.h"
#include "support/allocation_counter.h"
#include "support/data_server_host.h"
#include "support/test_data.h"

namespace nq {
namespace {

using DataHost = test::DataServerHost;

TEST(EngineGameAlloc, HuntedPlayerFramesAllocateNothingOnceWarm) {
    DataHost host;
    LiveGame game(host);
    ASSERT_EQ(game.start("e2m3", {}), "");
    ClientState client;
    MoveCommand cmd;
    auto run = [&](int frames) {
        for (int i = 0; i < frames; ++i) {
            if (game.run_frame(client, LiveGame::kServerFrameTime, cmd) != FrameStatus::Playing) {
                return false;
            }
            client.prepare_frame(LerpMode::Interpolate);
            (void)client.take_console_text();
            (void)client.take_center_prints();
            (void)client.take_stuff_text();
        }
        return true;
    };
    ASSERT_TRUE(run(72));
    server::ServerLevel& level = *game.server().level();
    server::toggle_god(level);
    ASSERT_TRUE(server::wake_monsters(game.server(), 0.3));
    const int hunting = server::monsters_hunting_player(level);
    EXPECT_GE(hunting, 5);
    ASSERT_TRUE(run(10 * 72));  // warm: every buffer at its working size
    const long before = ::nq::test::g_allocations.load();
    ASSERT_TRUE(run(10 * 72));
    EXPECT_EQ(::nq::test::g_allocations.load() - before, 0)
        << "allocations over 720 frames with " << hunting << " monsters hunting";
}

}  // namespace
}  // namespace nq

// The game's frame allocates nothing once warm: on e2m3 with its monsters woken and hunting the
// god-mode player (projectiles, pain, deaths of monsters in crossfire), every frame's server
// work — client command, physics, QuakeC, messages — and the client's part of it — decoding and
// applying the messages, interpolation and effects — runs without a heap allocation.
#include <gtest/gtest.h>

#include "app/live_game.h"
#include "common/file_io.h"
#include "render_allocation_counter.h"
#include "server/monster_waking.h"
#include "server/server_commands.h"
#include "server/server_level.h"
#include "support/test_data.h"

namespace nq {
namespace {

class DataHost : public server::ServerHost {
  public:
    std::optional<std::vector<uint8_t>> read_file(std::string_view path) override {
        auto bytes = nq::read_file(test::lq1_dir() + "/" + std::string(path));
        if (!bytes) return std::nullopt;
        return std::move(*bytes);
    }
    void print(std::string_view) override {}
    void debug_print(std::string_view) override {}
    float cvar_value(std::string_view name) override { return name == "sv_aim" ? 1.0f : 0.0f; }
    std::string cvar_string(std::string_view) override { return ""; }
    void set_cvar(std::string_view, std::string_view) override {}
    void add_command(std::string_view) override {}
};

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
    const long before = render_test::g_allocations.load();
    ASSERT_TRUE(run(10 * 72));
    EXPECT_EQ(render_test::g_allocations.load() - before, 0)
        << "allocations over 720 frames with " << hunting << " monsters hunting";
}

}  // namespace
}  // namespace nq

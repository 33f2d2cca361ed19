// The engine's game wing on its own (no window, no renderer): GameController over a real host
// core, the LibreQuake data and a session. `map` starts a game through the engine's begin_game,
// frames run the server, `save` writes Quake's text format to the user's game dir and `load`
// brings the player back where the file says, `record` writes a demo that starts with the
// level's sign-on, a missing map and the cheats without a game are messages, and `gamestats`
// counts the frames the engine told it about.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>

#include <unistd.h>

#include "app/sessions/demo_session.h"
#include "app/game/game_controller.h"
#include "common/file_io.h"
#include "formats/dem.h"
#include "fs/vfs.h"
#include "server/server_level.h"
#include "support/test_data.h"

namespace nq {
namespace {

class GameControllerTest : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = std::filesystem::temp_directory_path() /
               ("nq_game_controller_" + std::to_string(::getpid()));
        std::filesystem::remove_all(dir_);
        auto vfs = Vfs::mount(VfsConfig::for_game(test::data_root(), "lq1"));
        ASSERT_TRUE(vfs) << vfs.error().message;
        vfs_.emplace(std::move(*vfs));
        host_.set_print([this](std::string_view t) { output_ += std::string(t) + "\n"; });
        DemoSessionCallbacks callbacks;
        callbacks.print = [this](std::string_view t) { output_ += std::string(t) + "\n"; };
        callbacks.center_print = [](std::string_view) {};
        callbacks.stuff_text = [this](std::string_view t) { host_.commands().add_text(t); };
        callbacks.level_unloading = [] {};
        callbacks.level_loaded = [](Level&) {};
        callbacks.level_restarted = [](Level&) {};
        session_ = std::make_unique<DemoSession>(&*vfs_, std::move(callbacks));
        input_ = std::make_unique<PlayerInput>(host_.commands());
        GameContext context;
        context.host = &host_;
        context.session = session_.get();
        context.input = input_.get();
        context.vfs = &*vfs_;
        context.user_game_dir = (dir_ / "lq1").string();
        context.print = [this](std::string_view t) { output_ += std::string(t) + "\n"; };
        context.begin_game = [this](std::unique_ptr<LiveGame> game, const std::string& map) {
            ++games_begun_;
            if (session_->active()) session_->stop();
            session_->start_game(std::move(game), map);
        };
        game_ = std::make_unique<GameController>(std::move(context));
    }

    void TearDown() override {
        game_.reset();
        session_.reset();
        std::filesystem::remove_all(dir_);
    }

    // Runs `text` through the command buffer, then `frames` game frames of 1/72 s.
    void run(const std::string& text, int frames = 0) {
        host_.commands().add_text(text + "\n");
        host_.commands().execute();
        for (int i = 0; i < frames && session_->live(); ++i) {
            game_->run_frame(1.0 / 72, false);
            game_->frame_drawn(0.004, true);
            host_.commands().execute();
        }
    }

    server::ServerLevel* level() {
        LiveGame* game = session_->live();
        return game && game->running() ? game->server().level() : nullptr;
    }

    // The player's origin (entity 1) as the server holds it.
    std::array<float, 3> player_origin() {
        server::ServerLevel& l = *level();
        const auto& f = l.layout.fields;
        const vm::Vec3f at = l.vm->field_vector(1, f.origin);
        return {at[0], at[1], at[2]};
    }

    std::filesystem::path dir_;
    std::optional<Vfs> vfs_;
    HostCore host_;
    std::unique_ptr<DemoSession> session_;
    std::unique_ptr<PlayerInput> input_;
    std::unique_ptr<GameController> game_;
    std::string output_;
    int games_begun_ = 0;
};

TEST_F(GameControllerTest, MapStartsAGameThroughTheEngineAndFramesRunTheServer) {
    run("map start", 30);
    ASSERT_NE(level(), nullptr) << output_;
    EXPECT_EQ(games_begun_, 1);
    EXPECT_EQ(level()->map_name, "start");
    EXPECT_TRUE(session_->client().signed_on());
    EXPECT_NE(output_.find("map start: loaded in"), std::string::npos) << output_;
    // A missing map is a message and the game goes on.
    run("map no_such_map", 2);
    EXPECT_NE(output_.find("map: cannot find maps/no_such_map.bsp; the game goes on"),
              std::string::npos)
        << output_;
    ASSERT_NE(level(), nullptr);
    EXPECT_EQ(games_begun_, 1);
}

TEST_F(GameControllerTest, CommandsThatNeedAGameSayThereIsNone) {
    run("god\nchangelevel start\nsave x\nkill\nrestart");
    EXPECT_NE(output_.find("no game is running"), std::string::npos) << output_;
    EXPECT_NE(output_.find("changelevel: no game is running (use map)"), std::string::npos);
    EXPECT_NE(output_.find("Not playing a local game."), std::string::npos);
    EXPECT_NE(output_.find("kill: no game is running"), std::string::npos);
    EXPECT_NE(output_.find("restart: no game is running"), std::string::npos);
    EXPECT_EQ(games_begun_, 0);
}

TEST_F(GameControllerTest, SaveWritesQuakesFormatAndLoadPutsThePlayerBack) {
    run("skill 2\nmap start", 30);
    ASSERT_NE(level(), nullptr) << output_;
    run("setpos 100 200 300", 1);
    const auto saved_at = player_origin();
    run("save slot1");
    const auto path = dir_ / "lq1" / "slot1.sav";
    ASSERT_TRUE(std::filesystem::exists(path)) << output_;
    const auto bytes = read_file(path.string());
    ASSERT_TRUE(bytes);
    const std::string text(bytes->begin(), bytes->end());
    // Quake's layout: the version 5 on the first line, then the comment; the map name follows
    // the 16 spawn parms and the skill, computed from the file's own lines.
    EXPECT_EQ(text.substr(0, 2), "5\n");
    std::vector<std::string> lines;
    for (size_t at = 0, end; (end = text.find('\n', at)) != std::string::npos; at = end + 1) {
        lines.push_back(text.substr(at, end - at));
    }
    ASSERT_GT(lines.size(), 20u);
    EXPECT_EQ(std::stof(lines[18]), 2.0f);  // skill
    EXPECT_EQ(lines[19], "start");

    run("setpos 0 0 0\nskill 0", 1);
    run("load slot1", 1);
    ASSERT_NE(level(), nullptr) << output_;
    EXPECT_EQ(games_begun_, 2);
    EXPECT_NE(output_.find("Loaded game slot1.sav (start)"), std::string::npos) << output_;
    EXPECT_EQ(host_.cvars().find("skill")->integer(), 2);
    const auto loaded_at = player_origin();
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(loaded_at[k], saved_at[k], 1.0f) << k;
}

TEST_F(GameControllerTest, RecordWritesADemoOfTheGame) {
    run("record walk start", 20);
    ASSERT_NE(level(), nullptr) << output_;
    EXPECT_TRUE(game_->stop_recording());
    EXPECT_FALSE(game_->stop_recording());  // nothing to stop any more
    const auto path = dir_ / "lq1" / "walk.dem";
    const auto bytes = read_file(path.string());
    ASSERT_TRUE(bytes) << output_;
    const Result<Demo> dem = parse_dem(*bytes, path.string());
    ASSERT_TRUE(dem) << dem.error().to_string();
    EXPECT_GE(dem->blocks.size(), 20u);  // the sign-on, then a block per frame at least
    EXPECT_NE(output_.find("completed demo " + path.string()), std::string::npos) << output_;
}

TEST_F(GameControllerTest, GamestatsCountsTheFramesItWasTold) {
    run("map start", 11);
    output_.clear();
    run("gamestats");
    // Eleven frames of 4 ms: the first is left out, 250 fps.
    const std::regex frames(R"(game: (\d+) frames)");
    std::smatch m;
    ASSERT_TRUE(std::regex_search(output_, m, frames)) << output_;
    EXPECT_EQ(std::stoi(m[1]), 10) << output_;
    EXPECT_NE(output_.find("median 4.00 ms"), std::string::npos) << output_;
}

}  // namespace
}  // namespace nq

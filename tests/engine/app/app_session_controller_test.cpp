// The engine's sessions wing on its own (no window, no renderer): SessionController over a real
// host core, the LibreQuake data and a timedemo wing. A timedemo plays to its end and the
// timedemo wing reports the frames the session counted; startdemos skips demos that are not
// here and loops the rest; a missing demo is a message (a failed timedemo of the command line
// fails the process); pause and viewpos answer with and without a session; the showroom and
// the renderer's level callbacks are asked for at the right moments.
#include <gtest/gtest.h>

#include <regex>

#include "app/sessions/session_controller.h"
#include "fs/vfs.h"
#include "support/engine_run.h"
#include "support/test_data.h"

namespace nq {
namespace {

class SessionControllerTest : public ::testing::Test {
  protected:
    void SetUp() override {
        auto vfs = Vfs::mount(VfsConfig::for_game(test::data_root(), "lq1"));
        ASSERT_TRUE(vfs) << vfs.error().message;
        vfs_.emplace(std::move(*vfs));
        auto print = [this](std::string_view t) { output_ += std::string(t) + "\n"; };
        host_.set_print(print);
        TimedemoContext timedemo;
        timedemo.host = &host_;
        timedemo.options = &options_;
        timedemo.user_game_dir = dir_.path();
        timedemo.print = print;
        timedemo.quit = [this] { quit_ = true; };
        timedemo.fail_process = [this] { ++failures_; };
        timedemo_.emplace(std::move(timedemo));
        SessionContext context;
        context.host = &host_;
        context.vfs = &*vfs_;
        context.options = &options_;
        context.timedemo = &*timedemo_;
        context.user_game_dir = dir_.path();
        context.print = print;
        context.center_print = [](std::string_view) {};
        context.show_showroom = [this](bool on) { showroom_calls_ += on ? "+" : "-"; };
        context.describe_renderer = [] {
            TimedemoRun run;
            run.plugin = "test";
            return run;
        };
        context.quitting = [this] { return quit_; };
        context.level_loaded = [this](Level&) { ++levels_loaded_; };
        context.level_restarted = [](Level&) {};
        context.level_unloading = [] {};
        sessions_.emplace(std::move(context));
        sessions_->register_commands();
        timedemo_->register_commands(host_.commands());
    }

    void run(const std::string& text) {
        host_.commands().add_text(text + "\n");
        host_.commands().execute();
    }

    // Frames of 1/72 s until the session ends (or `limit`); returns the timedemo frames.
    int play(int limit) {
        int counted = 0;
        for (int i = 0; i < limit && sessions_->session().active(); ++i) {
            const SessionFrame frame = sessions_->run_frame(1.0 / 72, false, false);
            if (frame.timedemo_frame) {
                timedemo_->record_frame(0.01);
                ++counted;
            }
            sessions_->frame_drawn(0.01, frame);
            host_.commands().execute();
        }
        return counted;
    }

    test::TempDir dir_{"nq_session_controller"};
    std::optional<Vfs> vfs_;
    HostCore host_;
    LaunchOptions options_;
    std::optional<TimedemoController> timedemo_;
    std::optional<SessionController> sessions_;
    std::string output_;
    std::string showroom_calls_;
    bool quit_ = false;
    int failures_ = 0;
    int levels_loaded_ = 0;
};

TEST_F(SessionControllerTest, ATimedemoPlaysToItsEndAndReportsTheFramesItCounted) {
    run("timedemo demo");
    ASSERT_TRUE(sessions_->session().active()) << output_;
    EXPECT_EQ(sessions_->session().mode(), DemoMode::TimeDemo);
    EXPECT_EQ(showroom_calls_, "-") << "a demo hides the showroom";
    const int counted = play(100000);
    EXPECT_FALSE(sessions_->session().active()) << "demo.dem ends";
    EXPECT_GT(counted, 100);
    EXPECT_GE(levels_loaded_, 1);
    // Quake's line counts every frame but the first.
    const std::regex line(std::to_string(counted - 1) + R"( frames +[0-9.]+ seconds +[0-9.]+ fps)");
    EXPECT_TRUE(std::regex_search(output_, line)) << output_;
    EXPECT_EQ(failures_, 0);
}

TEST_F(SessionControllerTest, StartdemosSkipsAbsentDemosAndLoopsTheRest) {
    run("startdemos nosuchdemo demo");
    EXPECT_NE(output_.find("startdemos: nosuchdemo is not here, skipped"), std::string::npos)
        << output_;
    EXPECT_NE(output_.find("1 demo(s) in loop: demo"), std::string::npos) << output_;
    ASSERT_TRUE(sessions_->session().active());
    EXPECT_EQ(sessions_->session().mode(), DemoMode::Playback);
    EXPECT_EQ(sessions_->session().name(), "demo");
    play(200);
    run("stopdemo");
    EXPECT_FALSE(sessions_->session().active());
}

TEST_F(SessionControllerTest, AMissingDemoIsAMessageAndAFailedTimedemoFailsTheJob) {
    run("playdemo nosuchdemo");
    EXPECT_FALSE(sessions_->session().active());
    EXPECT_NE(output_.find("nosuchdemo"), std::string::npos) << output_;
    EXPECT_EQ(failures_, 0) << "playdemo's failure is only a message";
    run("timedemo nosuchdemo");
    EXPECT_NE(output_.find("timedemo nosuchdemo failed (no frame rate reported)"),
              std::string::npos)
        << output_;
    EXPECT_EQ(failures_, 1) << "a timedemo the command line asked for failed";
    EXPECT_EQ(showroom_calls_, "") << "nothing started: the screen stays as it was";
}

TEST_F(SessionControllerTest, PauseAndViewposAnswerWithAndWithoutASession) {
    run("pause");
    run("viewpos");
    EXPECT_NE(output_.find("pause: no demo is playing"), std::string::npos) << output_;
    EXPECT_NE(output_.find("viewpos: no game or demo is running"), std::string::npos);
    run("playdemo demo");
    play(300);
    ASSERT_TRUE(sessions_->session().active());
    output_.clear();
    run("pause");
    EXPECT_TRUE(sessions_->session().paused());
    const SessionFrame frame = sessions_->run_frame(1.0 / 72, false, false);
    EXPECT_FALSE(frame.timedemo_frame);
    run("pause 0");
    EXPECT_FALSE(sessions_->session().paused());
    run("viewpos");
    EXPECT_TRUE(std::regex_search(
        output_, std::regex(R"(viewpos: time [0-9.]+ origin -?[0-9.]+ -?[0-9.]+ -?[0-9.]+)")))
        << output_;
    run("stop");  // no recording: stops the demo
    EXPECT_FALSE(sessions_->session().active());
}

}  // namespace
}  // namespace nq

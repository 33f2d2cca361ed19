// The engine's timedemo wing on its own (no window, no demo): TimedemoController over a real
// host core. demo_at queues commands at the demo frame asked for; the command line's remaining
// text waits for a demo and runs when it ends; a timedemo's report is Quake's line over the
// counted frames (the first excluded); a timedemo with no frame, or one the demo failed, gives
// no frame rate and fails the process only when the command line started it; -benchmark runs
// the demo N times, logs one line and quits.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "app/timedemo/timedemo_controller.h"
#include "common/file_io.h"
#include "support/engine_run.h"

namespace nq {
namespace {

class TimedemoControllerTest : public ::testing::Test {
  protected:
    void make(LaunchOptions options = {}) {
        options_ = std::move(options);
        host_.set_print([this](std::string_view t) { output_ += std::string(t) + "\n"; });
        TimedemoContext context;
        context.host = &host_;
        context.options = &options_;
        context.user_game_dir = dir_.path() + "/lq1";
        context.print = [this](std::string_view t) { output_ += std::string(t) + "\n"; };
        context.quit = [this] { ++quits_; };
        context.fail_process = [this] { ++failures_; };
        controller_.emplace(std::move(context));
        controller_->register_commands(host_.commands());
    }

    TimedemoRun run_of(const std::string& demo) const {
        TimedemoRun run;
        run.demo = demo;
        run.plugin = "classic";
        run.width = 320;
        run.height = 240;
        return run;
    }

    // A timedemo that plays `frame_seconds` (the first one is the load frame, not counted).
    void play(const std::vector<double>& frame_seconds, const std::string& failure = {}) {
        controller_->demo_requested();
        controller_->demo_started();
        for (double s : frame_seconds) controller_->record_frame(s);
        TimedemoRun run = run_of("demo");
        run.failure = failure;
        controller_->finish_timedemo(run);
        controller_->demo_ended(true, quits_ > 0);
    }

    test::TempDir dir_{"nq_timedemo_controller"};
    HostCore host_;
    LaunchOptions options_;
    std::optional<TimedemoController> controller_;
    std::string output_;
    int quits_ = 0;
    int failures_ = 0;
};

TEST_F(TimedemoControllerTest, DemoAtQueuesItsCommandsWhenTheDemoReachesTheFrame) {
    make();
    host_.commands().add_text("demo_at 5 \"echo five\"\ndemo_at 2 \"echo two\"\n");
    host_.commands().execute();
    ASSERT_TRUE(host_.commands().buffer_empty());
    controller_->run_schedule(1);
    EXPECT_TRUE(host_.commands().buffer_empty());
    controller_->run_schedule(3);
    EXPECT_EQ(host_.commands().take_pending_text(), "echo two\n");
    controller_->run_schedule(9);
    EXPECT_EQ(host_.commands().take_pending_text(), "echo five\n");
    controller_->run_schedule(20);  // each runs once
    EXPECT_TRUE(host_.commands().buffer_empty());
}

TEST_F(TimedemoControllerTest, AnEndedDemoDropsWhatItsScheduleDidNotReach) {
    make();
    host_.commands().add_text("demo_at 100 \"echo late\"\n");
    host_.commands().execute();
    controller_->demo_ended(false, false);
    controller_->run_schedule(1000);
    EXPECT_TRUE(host_.commands().buffer_empty());
}

TEST_F(TimedemoControllerTest, TheRestOfTheCommandLineWaitsForTheDemo) {
    make();
    host_.commands().add_text("echo after\nquit\n");
    controller_->demo_requested();
    controller_->demo_started();
    EXPECT_TRUE(host_.commands().buffer_empty()) << "the text must wait for the demo's end";
    controller_->demo_ended(false, false);
    EXPECT_EQ(host_.commands().take_pending_text(), "echo after\nquit\n");
}

TEST_F(TimedemoControllerTest, ReportIsQuakesLineOverTheCountedFrames) {
    make();
    play({0.5, 0.010, 0.020, 0.030});
    char expected[128];
    std::snprintf(expected, sizeof expected, "%i frames %5.1f seconds %5.1f fps", 3, 0.06,
                  3 / 0.06);
    EXPECT_NE(output_.find(expected), std::string::npos) << output_;
    EXPECT_NE(output_.find("median 20.00 ms"), std::string::npos) << output_;
    EXPECT_EQ(failures_, 0);
}

TEST_F(TimedemoControllerTest, NoFrameOrAFailedDemoGivesNoFrameRateAndFailsTheJob) {
    make();
    play({0.5});  // only the load frame: nothing counted
    EXPECT_NE(output_.find("timedemo demo failed (no frame rate reported): no frame was played"),
              std::string::npos)
        << output_;
    EXPECT_EQ(output_.find(" fps"), std::string::npos) << output_;
    EXPECT_EQ(failures_, 1) << "the command line started it: its failure is the exit status";

    output_.clear();
    play({0.5, 0.01, 0.01}, "demo.dem: offset 1234: bad message");
    EXPECT_NE(output_.find("failed (no frame rate reported): demo.dem: offset 1234"),
              std::string::npos)
        << output_;
    EXPECT_EQ(output_.find(" fps"), std::string::npos) << output_;
}

TEST_F(TimedemoControllerTest, AFailureOutsideTheCommandLinesJobIsOnlyAMessage) {
    make();
    controller_->update_command_line_job(false);  // nothing pending: the job is over
    EXPECT_FALSE(controller_->after_command_line_demo());
    play({0.5});
    EXPECT_NE(output_.find("no frame was played"), std::string::npos);
    EXPECT_EQ(failures_, 0);
}

TEST_F(TimedemoControllerTest, TheJobLastsWhileItsDemoPlaysAndItsTextWaits) {
    make();
    host_.commands().add_text("quit\n");
    controller_->demo_requested();
    controller_->demo_started();
    EXPECT_TRUE(controller_->after_command_line_demo());
    controller_->update_command_line_job(true);
    EXPECT_TRUE(controller_->after_command_line_demo()) << "text still waits for the demo";
    controller_->demo_ended(false, false);
    host_.commands().take_pending_text();
    controller_->update_command_line_job(true);
    EXPECT_TRUE(controller_->after_command_line_demo()) << "its demo is still playing";
    controller_->update_command_line_job(false);
    EXPECT_FALSE(controller_->after_command_line_demo());
}

TEST_F(TimedemoControllerTest, BenchmarkRunsTheDemoNTimesThenLogsAndQuits) {
    LaunchOptions options;
    options.benchmark = "demo";
    options.benchmark_runs = 2;
    make(options);
    controller_->queue_benchmark();
    EXPECT_EQ(host_.commands().take_pending_text(), "timedemo \"demo\"\n");
    play({0.5, 0.01, 0.01});
    EXPECT_EQ(quits_, 0);
    EXPECT_EQ(host_.commands().take_pending_text(), "timedemo \"demo\"\n") << "the second run";
    play({0.5, 0.02, 0.02});
    EXPECT_EQ(quits_, 1);
    EXPECT_TRUE(host_.commands().buffer_empty()) << "no third run";
    EXPECT_NE(output_.find("benchmark demo: 2 runs, fps min 50.0 median 75.0 max 100.0"),
              std::string::npos)
        << output_;
    auto log = read_file(dir_.path() + "/lq1/benchmark.log");
    ASSERT_TRUE(log) << log.error().message;
    const std::string text(log->begin(), log->end());
    EXPECT_NE(text.find("classic"), std::string::npos) << text;
    EXPECT_NE(text.find("320x240"), std::string::npos) << text;
    EXPECT_EQ(failures_, 0);
}

TEST_F(TimedemoControllerTest, AFailedBenchmarkRunEndsItWithAFailure) {
    LaunchOptions options;
    options.benchmark = "demo";
    options.benchmark_runs = 3;
    make(options);
    controller_->queue_benchmark();
    host_.commands().take_pending_text();
    play({0.5, 0.01});
    EXPECT_EQ(host_.commands().take_pending_text(), "timedemo \"demo\"\n") << "the second run";
    play({0.5});
    EXPECT_EQ(quits_, 1);
    EXPECT_GE(failures_, 1);
    EXPECT_NE(output_.find("benchmark demo failed after 1 of 3 runs"), std::string::npos)
        << output_;
    EXPECT_TRUE(host_.commands().buffer_empty()) << "no run after the failure";
    auto log = read_file(dir_.path() + "/lq1/benchmark.log");
    ASSERT_TRUE(log);
    EXPECT_NE(std::string(log->begin(), log->end()).find("FAILED"), std::string::npos);
}

}  // namespace
}  // namespace nq

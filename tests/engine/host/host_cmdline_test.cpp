#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "host/command_line.h"
#include "host/launch_options.h"
#include "host_test_fixture.h"

namespace nq {
namespace {

using Args = std::vector<std::string>;

TEST(HostCommandLine, TheIssueExample) {
    // nprquake -basedir ../shared/data -game lq1 +timedemo demo +quit
    CommandLine line = CommandLine::parse(
        {"-basedir", "../shared/data", "-game", "lq1", "+timedemo", "demo", "+quit"});
    EXPECT_TRUE(line.has("-basedir"));
    EXPECT_EQ(line.value("-basedir"), "../shared/data");
    EXPECT_EQ(line.value("-game"), "lq1");
    EXPECT_FALSE(line.has("-window"));
    EXPECT_EQ(line.value("-width"), std::nullopt);
    EXPECT_EQ(line.command_text(), "timedemo demo\nquit\n");
    EXPECT_TRUE(line.stray().empty());

    LaunchOptions options = read_launch_options(line);
    EXPECT_EQ(options.basedir, "../shared/data");
    EXPECT_EQ(options.game, "lq1");
    EXPECT_EQ(options.width, std::nullopt);
    EXPECT_EQ(options.fullscreen, std::nullopt);
    EXPECT_TRUE(options.errors.empty());
}

TEST(HostCommandLine, FromMainSkipsTheProgramName) {
    const char* argv[] = {"nprquake", "-window", "+map", "e1m1"};
    CommandLine line = CommandLine::from_main(4, argv);
    EXPECT_TRUE(line.has("-window"));
    EXPECT_FALSE(line.has("nprquake"));
    EXPECT_EQ(line.command_text(), "map e1m1\n");
}

TEST(HostCommandLine, FlagsWithAndWithoutValues) {
    CommandLine line = CommandLine::parse(
        {"-window", "-width", "1280", "-HEIGHT", "720", "-benchjson", "out/bench.json"});
    EXPECT_TRUE(line.has("-window"));
    EXPECT_EQ(line.value("-window"), std::nullopt);  // followed by a flag: no value
    EXPECT_EQ(line.value("-width"), "1280");
    EXPECT_EQ(line.value("-height"), "720");  // flags match case-insensitively
    LaunchOptions options = read_launch_options(line);
    EXPECT_EQ(options.width, 1280);
    EXPECT_EQ(options.height, 720);
    EXPECT_EQ(options.fullscreen, false);
    EXPECT_EQ(options.bench_json, "out/bench.json");
    EXPECT_TRUE(options.errors.empty());
}

TEST(HostCommandLine, BenchmarkOptions) {
    LaunchOptions options = read_launch_options(
        CommandLine::parse({"-benchmark", "demo2", "-benchmarkruns", "5", "-benchframes",
                            "frames.txt", "-benchtrace", "trace.tsv"}));
    EXPECT_EQ(options.benchmark, "demo2");
    EXPECT_EQ(options.benchmark_runs, 5);
    EXPECT_EQ(options.bench_frames, "frames.txt");
    EXPECT_EQ(options.bench_trace, "trace.tsv");
    EXPECT_FALSE(read_launch_options(CommandLine::parse({"-benchtrace"})).bench_trace);
    EXPECT_TRUE(options.errors.empty());
    EXPECT_EQ(read_launch_options(CommandLine::parse({"-benchmark", "demo"})).benchmark_runs, 1);

    for (const char* bad : {"0", "-3", "1001", "x", "2.5"}) {
        LaunchOptions o = read_launch_options(CommandLine::parse({"-benchmarkruns", bad}));
        ASSERT_EQ(o.errors.size(), 1u) << bad;
        EXPECT_NE(o.errors[0].find("-benchmarkruns"), std::string::npos) << o.errors[0];
        EXPECT_EQ(o.benchmark_runs, 1) << bad;
    }
}

TEST(HostCommandLine, TheLaterOfWindowAndFullscreenWins) {
    EXPECT_EQ(read_launch_options(CommandLine::parse({"-window", "-fullscreen"})).fullscreen, true);
    EXPECT_EQ(read_launch_options(CommandLine::parse({"-fullscreen", "-window"})).fullscreen,
              false);
}

TEST(HostCommandLine, RepeatedFlagsLastOneWins) {
    CommandLine line = CommandLine::parse({"-game", "id1", "-game", "lq1"});
    EXPECT_EQ(line.value("-game"), "lq1");
}

TEST(HostCommandLine, EachPlusStartsACommandAndFlagsEndIt) {
    CommandLine line = CommandLine::parse({"+set", "volume", "-1", "+exec", "my.cfg", "-window",
                                           "+echo", "hello world", "+echo", "a;quit", "+echo", ""});
    EXPECT_EQ(line.command_text(),
              "set volume -1\nexec my.cfg\necho \"hello world\"\necho \"a;quit\"\necho \"\"\n");
    EXPECT_TRUE(line.has("-window"));
    EXPECT_EQ(line.value("-window"), std::nullopt);
}

TEST(HostCommandLine, StrayTokensAndLoneSigns) {
    CommandLine line = CommandLine::parse({"demo.dem", "+", "-", "-game", "lq1"});
    EXPECT_EQ(line.stray(), (Args{"demo.dem", "+", "-"}));
    EXPECT_EQ(line.command_text(), "");
}

TEST(HostCommandLine, BadValuesAreReported) {
    LaunchOptions options = read_launch_options(
        CommandLine::parse({"-width", "wide", "-height", "0", "-game", "../etc", "-basedir"}));
    EXPECT_EQ(options.errors,
              (Args{"-basedir needs a directory",
                    "-game: \"../etc\" must be a single directory name under the base "
                    "directory, not a path",
                    "-width: expected a whole number from 1 to 16384, got \"wide\"",
                    "-height: expected a whole number from 1 to 16384, got \"0\""}));
    EXPECT_EQ(options.width, std::nullopt);
    EXPECT_EQ(options.height, std::nullopt);
    EXPECT_EQ(options.game, std::nullopt);
    EXPECT_EQ(options.basedir, std::nullopt);
    EXPECT_EQ(read_launch_options(CommandLine::parse({"-width", "99999"})).errors,
              (Args{"-width: expected a whole number from 1 to 16384, got \"99999\""}));
    EXPECT_EQ(read_launch_options(CommandLine::parse({"-height", "-window"})).errors,
              (Args{"-height needs a size in pixels"}));
}

class HostStartup : public test::HostFixture {};

TEST_F(HostStartup, ConfigRunsBeforeTheCommandLine) {
    files["config.cfg"] = "seta volume 0.3\necho config";
    CommandLine line = CommandLine::parse({"-game", "lq1", "+volume", "0.9", "+echo", "cmdline"});
    host.queue_startup(line);
    EXPECT_EQ(frame(), "execing config.cfg\nconfig\ncmdline\n");  // no autoexec.cfg: silent
    EXPECT_EQ(host.cvars().find("volume")->string(), "0.9");
}

TEST_F(HostStartup, AutoexecRunsAfterConfig) {
    files["config.cfg"] = "echo 1";
    files["autoexec.cfg"] = "echo 2";
    host.queue_startup(CommandLine::parse({"+echo", "3"}));
    EXPECT_EQ(frame(), "execing config.cfg\n1\nexecing autoexec.cfg\n2\n3\n");
}

TEST_F(HostStartup, TimedemoChainWaitsBetweenFrames) {
    // What a benchmark script does: +commands spread over frames with wait.
    host.commands().add_command(
        "timedemo", [this](const CommandArgs& a) { output += "[timedemo " + a.argv(1) + "]\n"; });
    host.commands().add_command("quit", [this](const CommandArgs&) { output += "[quit]\n"; });
    host.queue_startup(CommandLine::parse({"+timedemo", "demo", "+wait", "+quit"}));
    EXPECT_EQ(frame(), "[timedemo demo]\n");
    EXPECT_EQ(frame(), "[quit]\n");
}

}  // namespace
}  // namespace nq

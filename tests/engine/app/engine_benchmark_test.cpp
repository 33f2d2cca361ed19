// `-benchmark DEMO -benchmarkruns N` and `-benchframes FILE` through the engine binary: N
// timedemos, a spread that agrees with the runs' own timedemo lines, one benchmark.log line,
// every counted frame time in the frames file; a failed benchmark reports no figure. And
// deterministic playback: two timedemos of one demo draw the same frame, particles included.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>

#include "common/file_io.h"
#include "support/engine_demo_replay.h"
#include "support/engine_image_checks.h"
#include "support/engine_output_checks.h"
#include "support/engine_runs.h"
#include "support/engine_run.h"

namespace nq {
namespace {

using namespace test;

std::vector<std::string> file_lines(const std::string& path) {
    std::ifstream in(path);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

// One timedemo's section of a -benchframes file.
struct FramesSection {
    std::string header;
    std::vector<double> ms;
};

std::vector<FramesSection> frames_sections(const std::string& path) {
    std::vector<FramesSection> sections;
    for (const std::string& line : file_lines(path)) {
        if (line.rfind("# ", 0) == 0) {
            sections.push_back({line, {}});
        } else if (!sections.empty()) {
            sections.back().ms.push_back(std::stod(line));
        }
    }
    return sections;
}

// The value after `label` in `line` ("fps min 98.1 median ...", label "min ").
double number_after(const std::string& line, const std::string& label) {
    std::smatch m;
    if (!std::regex_search(line, m, std::regex(label + "([0-9.]+)"))) return -1;
    return std::stod(m[1]);
}

TEST(EngineBenchmark, RunsTheTimedemoNTimesAndReportsTheSpreadOfTheirFrameRates) {
    TempDir dir("nq_engine_benchmark");
    auto args = engine_runs::base_args(dir.path(), data_root(), "lq1");
    engine_runs::add(args, {"-benchmark", "demo", "-benchmarkruns", "2", "-benchframes",
                            dir.file("frames.txt"), "+r_plugin", "null"});
    ProcessResult r = run_nprquake(args, dir.path(), 300);
    expect_clean_exit(r);

    Vfs vfs = mount_lq1();
    const uint64_t frames = timedemo_frame_count(vfs, "demo.dem");
    auto runs = timedemo_lines(r.out);
    ASSERT_EQ(runs.size(), 2u) << r.out;
    for (const TimedemoLine& run : runs) EXPECT_EQ(run.frames, frames);

    // The spread agrees with the two runs' own lines (each fps printed to 0.1).
    auto reports = lines_containing(r.out, "benchmark demo: 2 runs");
    ASSERT_EQ(reports.size(), 1u) << r.out;
    const double low = std::min(runs[0].fps, runs[1].fps);
    const double high = std::max(runs[0].fps, runs[1].fps);
    EXPECT_NEAR(number_after(reports[0], "fps min "), low, 0.06) << reports[0];
    EXPECT_NEAR(number_after(reports[0], " max "), high, 0.06) << reports[0];
    EXPECT_NEAR(number_after(reports[0], "fps min [0-9.]+ median "), (low + high) / 2, 0.06)
        << reports[0];

    // benchmark.log: one line with the date, the GL renderer, the command line, the figures.
    auto log = file_lines(dir.path() + "/user/lq1/benchmark.log");
    ASSERT_EQ(log.size(), 1u);
    EXPECT_TRUE(std::regex_search(log[0], std::regex(R"(^\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ )")))
        << log[0];
    auto renderer = lines_containing(r.out, "GL_RENDERER: ");
    ASSERT_EQ(renderer.size(), 1u) << r.out;
    EXPECT_NE(log[0].find("GL_RENDERER " + renderer[0].substr(13)), std::string::npos) << log[0];
    EXPECT_NE(log[0].find(reports[0]), std::string::npos) << log[0];
    EXPECT_NE(log[0].find("-benchmark demo -benchmarkruns 2"), std::string::npos) << log[0];

    // -benchframes: each run's counted frames, adding up to its reported seconds.
    auto sections = frames_sections(dir.file("frames.txt"));
    ASSERT_EQ(sections.size(), 2u);
    for (size_t i = 0; i < sections.size(); ++i) {
        EXPECT_EQ(sections[i].header, "# demo null 320x240 " + std::to_string(frames));
        EXPECT_EQ(sections[i].ms.size(), frames);
        double seconds = 0;
        for (double ms : sections[i].ms) seconds += ms / 1000;
        EXPECT_NEAR(seconds, runs[i].seconds, 0.06);
    }
}

// Splits a tab-separated line.
std::vector<std::string> tab_fields(const std::string& line) {
    std::vector<std::string> fields;
    std::stringstream in(line);
    for (std::string field; std::getline(in, field, '\t');) fields.push_back(field);
    if (!line.empty() && line.back() == '\t') fields.push_back("");
    return fields;
}

// -benchtrace: a row per counted frame whose stages add up to the frame time the timedemo
// measured itself (-benchframes, an independent clock reading), GPU pass times read back for
// every frame, and what each frame held.
TEST(EngineBenchmark, TraceExplainsEveryCountedFrame) {
    TempDir dir("nq_engine_trace");
    auto args = engine_runs::base_args(dir.path(), data_root(), "lq1");
    engine_runs::add(args, {"-benchmark", "demo", "-benchframes", dir.file("frames.txt"),
                            "-benchtrace", dir.file("trace.tsv"), "+r_plugin", "classic"});
    ProcessResult r = run_nprquake(args, dir.path(), 300);
    expect_clean_exit(r);
    Vfs vfs = mount_lq1();
    const uint64_t frames = timedemo_frame_count(vfs, "demo.dem");
    auto sections = frames_sections(dir.file("frames.txt"));
    ASSERT_EQ(sections.size(), 1u);
    ASSERT_EQ(sections[0].ms.size(), frames);

    auto lines = file_lines(dir.file("trace.tsv"));
    ASSERT_EQ(lines.size(), frames + 2);
    EXPECT_EQ(lines[0], "# demo classic 320x240 " + std::to_string(frames));
    const auto columns = tab_fields(lines[1]);
    auto column = [&](const std::string& name) {
        auto it = std::find(columns.begin(), columns.end(), name);
        return it == columns.end() ? -1 : static_cast<int>(it - columns.begin());
    };
    const int total = column("total_ms"), world = column("world_ms"), sound = column("sound_ms");
    const int entities = column("entities"), gpu_world = column("gpu_world_ms");
    ASSERT_EQ(total, 1);
    ASSERT_GT(world, total);
    ASSERT_GT(sound, world);
    ASSERT_GE(entities, 0);
    // The engine prints the GPU passes when the driver can time them; then so does the trace.
    const bool gpu_timed = !lines_containing(r.out, "  gpu world").empty();
    EXPECT_EQ(gpu_world >= 0, gpu_timed) << lines[1];

    size_t with_world = 0, with_entities = 0, with_gpu = 0, mismatched = 0;
    for (size_t i = 0; i < frames; ++i) {
        const auto row = tab_fields(lines[i + 2]);
        ASSERT_EQ(row.size(), columns.size()) << lines[i + 2];
        EXPECT_EQ(std::stoul(row[0]), i);
        double stages = 0;
        for (int c = total + 1; c <= sound; ++c) stages += std::stod(row[c]);
        const double frame_ms = sections[0].ms[i];
        EXPECT_NEAR(std::stod(row[total]), stages, 0.01 + 1e-4 * stages) << "frame " << i;
        // The two clocks are read a few statements apart: a busy machine can preempt in
        // between, so a few frames may differ by more.
        mismatched += std::abs(stages - frame_ms) > 0.3 + 0.03 * frame_ms;
        with_world += std::stod(row[world]) > 0;
        with_entities += std::stoul(row[entities]) > 0;
        with_gpu += gpu_world >= 0 && !row[gpu_world].empty();
    }
    EXPECT_LE(mismatched, frames / 100) << "frames whose stages do not add up to their time";
    EXPECT_EQ(with_world, frames);
    EXPECT_GT(with_entities, frames / 2);
    if (gpu_timed) {
        EXPECT_EQ(with_gpu, frames);
    }
}

TEST(EngineBenchmark, FailedBenchmarkExitsNonZeroAndLogsNoFigure) {
    TempDir dir("nq_engine_benchmark_fail");
    auto args = engine_runs::base_args(dir.path(), data_root(), "lq1");
    engine_runs::add(args, {"-benchmark", "no_such_demo", "-benchmarkruns", "3"});
    ProcessResult r = run_nprquake(args, dir.path(), 60);
    ASSERT_TRUE(r.spawned) << r.describe();
    EXPECT_FALSE(r.timed_out) << r.describe();
    EXPECT_EQ(r.exit_code, 1) << r.describe();
    EXPECT_EQ(sanitizer_report(r.err), "") << r.describe();
    EXPECT_TRUE(timedemo_lines(r.out).empty()) << r.out;
    EXPECT_EQ(lines_containing(r.out, "failed after 0 of 3 runs").size(), 1u) << r.out;
    auto log = file_lines(dir.path() + "/user/lq1/benchmark.log");
    ASSERT_EQ(log.size(), 1u);
    EXPECT_NE(log[0].find("FAILED"), std::string::npos) << log[0];
    // No figure before the command line (which itself says +scr_showfps).
    const std::string figures = log[0].substr(0, log[0].find("| command line:"));
    EXPECT_EQ(figures.find("fps"), std::string::npos) << log[0];
}

// Demo frame 1000 of demo.dem: thousands of particles (blood, spread by random numbers) in
// front of the player.
constexpr uint64_t kParticleFrame = 1000;

TEST(EngineBenchmark, TwoTimedemosOfOneDemoDrawTheSameFrame) {
    Vfs vfs = mount_lq1();
    DemoReplay replay(vfs, "demo.dem");
    ASSERT_TRUE(replay.play_to(kParticleFrame));
    ASSERT_GT(replay.client().particles().size(), 1000u) << "no subject for this test";

    // One process, two timedemos: the null renderer (fast) but for the frame compared.
    TempDir dir("nq_engine_same_frames");
    auto args = engine_runs::base_args(dir.path(), data_root(), "lq1");
    engine_runs::add(args, {"+r_plugin", "null"});
    for (const char* name : {"first", "second"}) {
        const std::string shot = dir.file(std::string(name) + ".png");
        engine_runs::demo_at(args, kParticleFrame - 2, "r_plugin classic");
        engine_runs::demo_at(args, kParticleFrame, "screenshot " + shot + "; r_plugin null");
        engine_runs::add(args, {"+timedemo", "demo"});
    }
    engine_runs::add(args, {"+quit"});
    ProcessResult r = run_nprquake(args, dir.path(), 300);
    expect_clean_exit(r);
    ASSERT_EQ(timedemo_lines(r.out).size(), 2u) << r.out;

    RgbImage first, second;
    ASSERT_NO_FATAL_FAILURE(load_screenshot(dir.file("first.png"), first));
    ASSERT_NO_FATAL_FAILURE(load_screenshot(dir.file("second.png"), second));
    RegionStats stats = region_stats(first, whole(first));
    ASSERT_GT(stats.distinct_colours, 100u) << "a blank frame proves nothing";
    ASSERT_EQ(first.rgb.size(), second.rgb.size());
    size_t differing = 0;
    for (size_t i = 0; i < first.rgb.size(); ++i) differing += first.rgb[i] != second.rgb[i];
    EXPECT_EQ(differing, 0u);
}

}  // namespace
}  // namespace nq

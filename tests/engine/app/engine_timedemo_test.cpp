// `timedemo` through the engine binary: it plays the LibreQuake demos to the end, reports
// Quake's "N frames S seconds F fps" line with the frame count an in-process replay gives,
// writes the -benchjson record, and refuses demos that are missing, cut short, corrupt or
// whose map is missing: a message, no frame rate, and (run by the command line) exit status 1.
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <regex>

#include "common/file_io.h"
#include "support/engine_demo_replay.h"
#include "support/engine_output_checks.h"
#include "support/engine_runs.h"
#include "support/engine_run.h"

namespace nq {
namespace {

using namespace test;

// Block layout of a .dem file, read with a few lines of independent code: a text line, then
// blocks of { int32 length, 3 float angles, message }.
struct BlockSpan {
    size_t header = 0;   // offset of the block's length field
    size_t message = 0;  // offset of its first message byte
    size_t length = 0;
};

std::vector<BlockSpan> demo_blocks(const std::vector<uint8_t>& bytes) {
    std::vector<BlockSpan> blocks;
    size_t at = std::find(bytes.begin(), bytes.end(), '\n') - bytes.begin() + 1;
    while (at + 16 <= bytes.size()) {
        int32_t length;
        std::memcpy(&length, &bytes[at], 4);
        if (length < 0 || at + 16 + size_t(length) > bytes.size()) break;
        blocks.push_back({at, at + 16, size_t(length)});
        at += 16 + length;
    }
    return blocks;
}

// The lines of `text` naming file offset `offset` ("offset 1234", not "offset 12345").
std::vector<std::string> lines_naming_offset(const std::string& text, size_t offset) {
    const std::regex pattern("offset " + std::to_string(offset) + "\\b");
    std::vector<std::string> out;
    for (const std::string& line : lines_containing(text, "offset ")) {
        if (std::regex_search(line, pattern)) out.push_back(line);
    }
    return out;
}

// The one timedemo line of a run, checked for self-consistency.
void expect_one_timedemo_line(const ProcessResult& r, uint64_t expected_frames) {
    auto lines = timedemo_lines(r.out);
    ASSERT_EQ(lines.size(), 1u) << "stdout:\n" << r.out;
    EXPECT_EQ(lines[0].frames, expected_frames);
    expect_consistent_fps(lines[0]);
}

TEST(EngineTimedemo, DemoPlaysToTheEndAndCountsEveryFrameButTheFirst) {
    const SharedRun& run = engine_runs::demo_classic();
    expect_clean_exit(run.result);
    Vfs vfs = mount_lq1();
    expect_one_timedemo_line(run.result, timedemo_frame_count(vfs, "demo.dem"));
}

TEST(EngineTimedemo, Demo2PlaysToTheEndAndCountsEveryFrameButTheFirst) {
    const SharedRun& run = engine_runs::demo2_swaps();
    expect_clean_exit(run.result);
    Vfs vfs = mount_lq1();
    expect_one_timedemo_line(run.result, timedemo_frame_count(vfs, "demo2.dem"));
}

TEST(EngineTimedemo, BenchJsonGetsOneRecordOfTheRun) {
    const SharedRun& run = engine_runs::demo2_swaps();
    expect_clean_exit(run.result);
    auto bytes = read_file(run.dir + "/bench.jsonl");
    ASSERT_TRUE(bytes) << bytes.error().to_string();
    std::string text(bytes->begin(), bytes->end());
    ASSERT_FALSE(text.empty());
    EXPECT_EQ(text.back(), '\n');
    ASSERT_EQ(std::count(text.begin(), text.end(), '\n'), 1) << text;

    EXPECT_NE(text.find(R"("demo":"demo2")"), std::string::npos) << text;
    EXPECT_NE(text.find(R"("plugin":"classic")"), std::string::npos) << text;  // active at the end
    EXPECT_NE(text.find(R"("width":320,"height":240)"), std::string::npos) << text;
    std::smatch frames, seconds, fps;
    ASSERT_TRUE(std::regex_search(text, frames, std::regex(R"("frames":(\d+)[,}])"))) << text;
    ASSERT_TRUE(std::regex_search(text, seconds, std::regex(R"("seconds":([0-9.eE+-]+))"))) << text;
    ASSERT_TRUE(std::regex_search(text, fps, std::regex(R"("fps":([0-9.eE+-]+))"))) << text;
    Vfs vfs = mount_lq1();
    EXPECT_EQ(std::stoull(frames[1]), timedemo_frame_count(vfs, "demo2.dem"));
    double s = std::stod(seconds[1]);
    ASSERT_GT(s, 0.0);
    EXPECT_NEAR(std::stod(fps[1]), std::stoull(frames[1]) / s, 0.01 * std::stod(fps[1]));
}

// A timedemo the command line ran failed: the engine ended by itself (after `+quit`), with
// exit status 1, no sanitizer report, one "timedemo <name> failed" line and no frame rate.
void expect_failed_timedemo(const ProcessResult& r, const std::string& name) {
    ASSERT_TRUE(r.spawned) << r.describe();
    EXPECT_FALSE(r.timed_out) << r.describe();
    EXPECT_EQ(r.signal, 0) << r.describe();
    EXPECT_EQ(r.exit_code, 1) << r.describe();
    EXPECT_EQ(sanitizer_report(r.err), "") << r.describe();
    EXPECT_EQ(lines_containing(r.out, "timedemo " + name + " failed").size(), 1u) << r.out;
    EXPECT_TRUE(timedemo_lines(r.out).empty()) << r.out;
    EXPECT_TRUE(lines_containing(r.out, "frame time:").empty()) << r.out;
}

TEST(EngineTimedemo, UnknownDemoIsNamedAndTheRunFails) {
    TempDir dir("nq_engine_nodemo");
    auto args = engine_runs::base_args(dir.path(), data_root(), "lq1");
    engine_runs::add(args, {"+timedemo", "no_such_demo", "+quit"});
    ProcessResult r = run_nprquake(args, dir.path(), 60);
    expect_failed_timedemo(r, "no_such_demo");
    auto named = lines_containing(r.out, "\"no_such_demo\"");
    ASSERT_EQ(named.size(), 1u) << r.out;
    EXPECT_NE(named[0].find("not found"), std::string::npos) << named[0];
}

// A game dir with nothing but `demo_bytes` as demo.dem (no palette, no maps: stand-ins).
ProcessResult timedemo_without_maps(const TempDir& dir, const std::vector<uint8_t>& demo_bytes) {
    std::string game = dir.subdir("base/g");
    EXPECT_EQ(write_file(game + "/demo.dem", demo_bytes), "");
    auto args = engine_runs::base_args(dir.path(), dir.path() + "/base", "g");
    engine_runs::add(args, {"+timedemo", "demo", "+quit"});
    return run_nprquake(args, dir.path(), 60);
}

// The LibreQuake game with `demo_bytes` as the user's cut.dem (the user dir is searched first).
ProcessResult timedemo_of(const TempDir& dir, const std::vector<uint8_t>& demo_bytes) {
    std::string user_game = dir.subdir("user/lq1");
    EXPECT_EQ(write_file(user_game + "/cut.dem", demo_bytes), "");
    auto args = engine_runs::base_args(dir.path(), data_root(), "lq1");
    engine_runs::add(args, {"+timedemo", "cut", "+quit"});
    return run_nprquake(args, dir.path(), 120);
}

TEST(EngineTimedemo, MissingMapFailsTheTimedemoNamingTheMap) {
    Vfs vfs = mount_lq1();
    TempDir dir("nq_engine_nomap");
    ProcessResult r = timedemo_without_maps(dir, read_game_file(vfs, "demo.dem"));
    expect_failed_timedemo(r, "demo");
    auto failed = lines_containing(r.out, "timedemo demo failed");
    ASSERT_EQ(failed.size(), 1u) << r.out;
    EXPECT_NE(failed[0].find("cannot load level"), std::string::npos) << failed[0];
    EXPECT_NE(failed[0].find("maps/start.bsp"), std::string::npos) << failed[0];
}

TEST(EngineTimedemo, MissingMapInAPlayedDemoIsAMessageNotAFailure) {
    Vfs vfs = mount_lq1();
    TempDir dir("nq_engine_nomap_play");
    std::string game = dir.subdir("base/g");
    ASSERT_EQ(write_file(game + "/demo.dem", read_game_file(vfs, "demo.dem")), "");
    auto args = engine_runs::base_args(dir.path(), dir.path() + "/base", "g");
    engine_runs::add(args, {"+playdemo", "demo", "+quit"});
    ProcessResult r = run_nprquake(args, dir.path(), 60);
    expect_clean_exit(r);
    EXPECT_EQ(lines_containing(r.out, "cannot load level").size(), 1u) << r.out;
    EXPECT_TRUE(timedemo_lines(r.out).empty()) << r.out;
}

TEST(EngineTimedemo, TruncatedDemoFailsNamingFileAndOffset) {
    Vfs vfs = mount_lq1();
    std::vector<uint8_t> bytes = read_game_file(vfs, "demo.dem");
    auto blocks = demo_blocks(bytes);
    ASSERT_GT(blocks.size(), 1000u);
    // Cut in the middle of a block's message, far enough in for the level to be playing.
    const BlockSpan& cut = blocks[blocks.size() / 3];
    ASSERT_GT(cut.length, 4u);
    bytes.resize(cut.message + cut.length / 2);

    TempDir dir("nq_engine_truncated");
    ProcessResult r = timedemo_of(dir, bytes);
    expect_failed_timedemo(r, "cut");
    auto at_offset = lines_naming_offset(r.out, cut.header);
    ASSERT_EQ(at_offset.size(), 1u) << "no line names offset " << cut.header << ":\n" << r.out;
    EXPECT_NE(at_offset[0].find("cut.dem"), std::string::npos)
        << "the message does not name the file: " << at_offset[0];
    EXPECT_NE(at_offset[0].find("timedemo cut failed"), std::string::npos) << at_offset[0];
}

TEST(EngineTimedemo, TruncatedDemoStillPlaysWithPlaydemo) {
    Vfs vfs = mount_lq1();
    std::vector<uint8_t> bytes = read_game_file(vfs, "demo.dem");
    auto blocks = demo_blocks(bytes);
    ASSERT_GT(blocks.size(), 1000u);
    // Early, so the demo plays out in recorded time within seconds.
    const BlockSpan& cut = blocks[60];
    ASSERT_GT(cut.length, 4u);
    bytes.resize(cut.message + cut.length / 2);

    TempDir dir("nq_engine_truncated_play");
    std::string user_game = dir.subdir("user/lq1");
    ASSERT_EQ(write_file(user_game + "/cut.dem", bytes), "");
    auto args = engine_runs::base_args(dir.path(), data_root(), "lq1");
    engine_runs::add(args, {"+playdemo", "cut", "+quit"});
    ProcessResult r = run_nprquake(args, dir.path(), 120);
    expect_clean_exit(r);
    EXPECT_EQ(lines_naming_offset(r.out, cut.header).size(), 1u) << r.out;  // a warning
    EXPECT_TRUE(lines_containing(r.out, "no frame rate reported").empty()) << r.out;
}

TEST(EngineTimedemo, CorruptMessageStopsTheDemoNamingFileAndOffset) {
    Vfs vfs = mount_lq1();
    std::vector<uint8_t> bytes = read_game_file(vfs, "demo.dem");
    auto blocks = demo_blocks(bytes);
    ASSERT_GT(blocks.size(), 200u);
    // Block 150 becomes a one-byte message holding server message number 100, which no
    // protocol defines; everything after it is dropped.
    const BlockSpan& bad = blocks[150];
    bytes.resize(bad.message + 1);
    const int32_t one = 1;
    std::memcpy(&bytes[bad.header], &one, 4);
    bytes[bad.message] = 100;

    TempDir dir("nq_engine_corrupt");
    ProcessResult r = timedemo_of(dir, bytes);
    expect_failed_timedemo(r, "cut");
    auto stopped = lines_containing(r.out, "demo stopped");
    ASSERT_EQ(stopped.size(), 1u) << r.out;
    EXPECT_NE(stopped[0].find("cut.dem"), std::string::npos) << stopped[0];
    EXPECT_EQ(lines_naming_offset(stopped[0], bad.message).size(), 1u)
        << "expected offset " << bad.message << ": " << stopped[0];
    EXPECT_NE(stopped[0].find("number 100"), std::string::npos) << stopped[0];
}

}  // namespace
}  // namespace nq

// The `mdltool info` command line, run as a separate process (binary from $NQ_BIN_DIR, which
// ctest sets to the build's bin/): over LibreQuake's progs/, over synthetic good and bad
// models, and with bad command lines.
#include <gtest/gtest.h>

#include <fstream>

#include "common/file_io.h"
#include "support/engine_run.h"
#include "support/json_checks.h"
#include "support/raw_bytes.h"
#include "support/synth_mdl.h"
#include "support/test_data.h"

namespace nq {
namespace {

using test::looks_like_json_object;
using test::TempDir;
using ToolRun = test::ProcessResult;

ToolRun run_mdltool(const std::vector<std::string>& args) {
    return test::run_tool("mdltool", args);
}

bool contains(const std::string& haystack, const std::string& needle) {
    return haystack.find(needle) != std::string::npos;
}

size_t count_of(const std::string& haystack, const std::string& needle) {
    size_t n = 0;
    for (size_t at = haystack.find(needle); at != std::string::npos;
         at = haystack.find(needle, at + 1)) {
        ++n;
    }
    return n;
}

std::string progs_dir() {
    return test::lq1_dir() + "/progs";
}

TEST(MdltoolInfo, ProgsDirectorySucceeds) {
    const ToolRun run = run_mdltool({"info", progs_dir()});
    EXPECT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(run.err, "");
    // One block per model, each starting with its path on a line of its own.
    EXPECT_EQ(count_of(run.out, "\n  version     6\n"), test::lq1_files("progs", ".mdl").size());
    EXPECT_TRUE(contains(run.out, "/player.mdl\n"));
    EXPECT_TRUE(contains(run.out, "  vertices    801\n"));
    EXPECT_TRUE(contains(run.out, "  triangles   1060\n"));
    EXPECT_TRUE(contains(run.out, "frame143\n"));
    EXPECT_TRUE(contains(run.out, "  flags       136 (rotate, tracer3)\n"));  // v_spike.mdl
    EXPECT_FALSE(contains(run.out, ".spr"));
}

TEST(MdltoolInfo, GroupsIntervalsAndEditorTrailers) {
    const ToolRun run = run_mdltool({"info", progs_dir() + "/flame.mdl"});
    EXPECT_EQ(run.exit_code, 0) << run.err;
    EXPECT_TRUE(contains(run.out, "group of 6: flame1 @0.1, flame2 @0.2")) << run.out;
    EXPECT_TRUE(contains(run.out, "QMEX")) << run.out;
    EXPECT_TRUE(contains(run.out, "  frames      1 (6 poses)\n")) << run.out;
}

TEST(MdltoolInfo, JsonOverProgs) {
    const ToolRun run = run_mdltool({"info", "--json", progs_dir()});
    EXPECT_EQ(run.exit_code, 0) << run.err;
    ASSERT_TRUE(looks_like_json_object(run.out)) << run.out.substr(0, 500);
    const size_t models = test::lq1_files("progs", ".mdl").size();
    EXPECT_EQ(count_of(run.out, "\"ok\": true"), models);
    EXPECT_EQ(count_of(run.out, "\"version\": 6,"), models);
    EXPECT_TRUE(contains(run.out, "\"num_verts\": 801,"));
    EXPECT_TRUE(contains(run.out, "\"sync_type_name\": \"sync\""));
    EXPECT_TRUE(contains(run.out, "\"failed\": 0"));
    EXPECT_TRUE(contains(run.out, "\"tracer3\""));
    EXPECT_TRUE(contains(run.out, "\"bbox\": {"));
}

TEST(MdltoolInfo, BadFileIsReportedAndTheRestStillRun) {
    TempDir dir;
    ASSERT_EQ(write_file(dir.file("good.mdl"), test::write_mdl(test::animated_mdl())), "");
    test::SynthMdl bad = test::minimal_mdl();
    bad.triangles[1].vertices[2] = 9;
    ASSERT_EQ(write_file(dir.file("BAD.MDL"), test::write_mdl(bad)), "");  // found despite case
    ASSERT_EQ(write_file(dir.file("readme.txt"), std::vector<uint8_t>{'h', 'i'}), "");
    // The bad triangle index field: header, 8x4 skin, 4 st verts, triangle 0, then 3 fields.
    const size_t offset = 84 + 4 + 32 + 4 * 12 + 16 + 4 + 2 * 4;

    ToolRun run = run_mdltool({"info", dir.path()});
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_TRUE(contains(run.err, "BAD.MDL: offset " + std::to_string(offset) +
                                      ": triangle 1 vertex 2 index 9 is out of range"))
        << run.err;
    EXPECT_TRUE(contains(run.out, "good.mdl\n")) << run.out;
    EXPECT_TRUE(contains(run.out, "group of 3: run1 @0.1, run2 @0.2, run3 @0.3")) << run.out;
    EXPECT_TRUE(contains(run.out, "(rotate, tracer)")) << run.out;
    EXPECT_FALSE(contains(run.out + run.err, "readme"));

    run = run_mdltool({"info", "--json", dir.path()});
    EXPECT_EQ(run.exit_code, 1);
    ASSERT_TRUE(looks_like_json_object(run.out)) << run.out;
    EXPECT_EQ(count_of(run.out, "\"ok\": false"), 1u);
    EXPECT_EQ(count_of(run.out, "\"ok\": true"), 1u);
    EXPECT_TRUE(contains(run.out, "\"offset\": " + std::to_string(offset)));
    EXPECT_TRUE(contains(run.out, "\"failed\": 1"));
}

TEST(MdltoolInfo, MissingPathsFailButOthersRun) {
    const ToolRun run = run_mdltool({"info", "/nonexistent/x.mdl", progs_dir() + "/gib1.mdl"});
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_TRUE(contains(run.err, "/nonexistent/x.mdl: no such file or directory")) << run.err;
    EXPECT_TRUE(contains(run.out, "gib1.mdl\n"));
    EXPECT_TRUE(contains(run.out, "(gib)"));
}

TEST(MdltoolInfo, EmptyDirectoryIsAFailure) {
    TempDir dir;
    const ToolRun run = run_mdltool({"info", dir.path()});
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_TRUE(contains(run.err, "no *.mdl files")) << run.err;
}

TEST(MdltoolUsage, BadCommandLinesExitWith2) {
    for (const auto& args : std::vector<std::vector<std::string>>{
             {}, {"frobnicate"}, {"info"}, {"info", "--json"}, {"info", "--frob", progs_dir()}}) {
        const ToolRun run = run_mdltool(args);
        EXPECT_EQ(run.exit_code, 2) << (args.empty() ? "(no args)" : args.back());
        EXPECT_TRUE(contains(run.err, "usage: mdltool")) << run.err;
        EXPECT_EQ(run.out, "");
    }
}

TEST(MdltoolUsage, HelpListsSubcommands) {
    ToolRun run = run_mdltool({"--help"});
    EXPECT_EQ(run.exit_code, 0);
    EXPECT_TRUE(contains(run.out, "info [--json] FILE|DIR..."));
    run = run_mdltool({"info", "--help"});
    EXPECT_EQ(run.exit_code, 0);
    EXPECT_TRUE(contains(run.out, "usage: mdltool info"));
}

}  // namespace
}  // namespace nq

// `mdltool adjacency` and `mdltool export`, run as separate processes (binary from $NQ_BIN_DIR):
// over LibreQuake's progs/, over synthetic models written as files and inside a pak, with
// malformed models among them, and with bad command lines.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/file_io.h"
#include "support/engine_run.h"
#include "support/json_checks.h"
#include "support/raw_bytes.h"
#include "support/synth_mdl.h"
#include "support/synth_pak.h"
#include "support/test_data.h"

namespace fs = std::filesystem;

namespace nq {
namespace {

using test::looks_like_json_object;
using test::TempDir;
using ToolRun = test::ProcessResult;

// Runs mdltool with `args` in directory `cwd` (default: the current one).
ToolRun run_mdltool(const std::vector<std::string>& args, const std::string& cwd = "") {
    return test::run_tool("mdltool", args, cwd);
}

std::string slurp(const std::string& path) {
    return test::text_file(path);
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

size_t lines_starting_with(const std::string& text, const std::string& prefix) {
    std::istringstream in(text);
    size_t n = 0;
    for (std::string line; std::getline(in, line);) n += line.rfind(prefix, 0) == 0;
    return n;
}

std::string progs_dir() {
    return test::lq1_dir() + "/progs";
}

// A 20-unit cube stored as MDL files do: every square has its own four vertices (texture
// seams), triangles clockwise seen from outside. Frame "a" at the packed origin, frame "b"
// moved by (100, 0, 0) packed units.
test::SynthMdl cube_mdl() {
    constexpr uint32_t kQuads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                       {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
    test::SynthMdl m = test::minimal_mdl();
    m.scale = {1, 1, 1};
    m.scale_origin = {0, 0, 0};
    m.tex_coords.clear();
    m.triangles.clear();
    m.frames.clear();
    test::SynthMdl::Pose a, b;
    a.name = "a";
    b.name = "b";
    for (uint32_t q = 0; q < 6; ++q) {
        for (uint32_t k = 0; k < 4; ++k) {
            const uint32_t c = kQuads[q][k];
            const uint8_t x = c & 1 ? 20 : 0, y = c & 2 ? 20 : 0, z = c & 4 ? 20 : 0;
            a.vertices.push_back({x, y, z, 0});
            b.vertices.push_back({uint8_t(x + 100), y, z, 0});
            m.tex_coords.push_back({0, int32_t(k & 1 ? 7 : 0), int32_t(k & 2 ? 3 : 0)});
        }
        const int32_t v = int32_t(4 * q);
        m.triangles.push_back({1, {v, v + 2, v + 1}});  // reversed: Quake's winding
        m.triangles.push_back({1, {v, v + 3, v + 2}});
    }
    a.bbox_max = {20, 20, 20, 0};
    b.bbox_min = {100, 0, 0, 0};
    b.bbox_max = {120, 20, 20, 0};
    m.frames.push_back({0, std::nullopt, {}, {}, {}, {a}});
    m.frames.push_back({0, std::nullopt, {}, {}, {}, {b}});
    return m;
}

test::SynthMdl bad_mdl() {
    test::SynthMdl bad = test::minimal_mdl();
    bad.triangles[1].vertices[2] = 9;
    return bad;
}

// The bad index's offset: header, 8x4 skin, 4 st vertices, triangle 0, then 3 fields.
constexpr size_t kBadOffset = 84 + 4 + 32 + 4 * 12 + 16 + 4 + 2 * 4;

TEST(MdltoolAdjacency, ProgsTableHasARowPerModelAndEveryCheckPasses) {
    const ToolRun run = run_mdltool({"adjacency", progs_dir()});
    EXPECT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(run.err, "");  // no progress bar: stderr is not a terminal
    const size_t models = test::lq1_files("progs", ".mdl").size();
    const std::string n = std::to_string(models);
    EXPECT_TRUE(contains(run.out, "consistency checks: " + n + "/" + n + " models passed\n"))
        << run.out;
    EXPECT_EQ(lines_starting_with(run.out, "player.mdl    1060 "), 1u) << run.out;
    EXPECT_EQ(count_of(run.out, "  true\n") + count_of(run.out, "  lines\n"), models);
    // The total row sums the headers' triangle counts (int32 at byte 64 of each file).
    int64_t triangles = 0;
    for (const std::string& path : test::lq1_files("progs", ".mdl")) {
        const std::string bytes = slurp(path);
        int32_t n = 0;
        std::memcpy(&n, bytes.data() + 64, 4);
        triangles += n;
    }
    char total[64];
    std::snprintf(total, sizeof total, "total        %5lld ", static_cast<long long>(triangles));
    EXPECT_EQ(lines_starting_with(run.out, total), 1u) << run.out;
    EXPECT_FALSE(contains(run.out, "CHECKS FAILED"));
}

TEST(MdltoolAdjacency, JsonOverProgs) {
    const ToolRun run = run_mdltool({"adjacency", "--json", progs_dir()});
    EXPECT_EQ(run.exit_code, 0) << run.err;
    ASSERT_TRUE(looks_like_json_object(run.out)) << run.out.substr(0, 400);
    const size_t models = test::lq1_files("progs", ".mdl").size();
    EXPECT_EQ(count_of(run.out, "\"checks_passed\": true"), models);
    EXPECT_EQ(count_of(run.out, "\"ok\": true"), models);
    EXPECT_TRUE(contains(run.out, "\"triangles\": 1060,"));
    EXPECT_TRUE(contains(run.out, "\"failed\": 0"));
    EXPECT_TRUE(contains(run.out, "\"paper\": {"));
}

TEST(MdltoolAdjacency, SyntheticCubeWeldsItsSeams) {
    TempDir dir;
    ASSERT_EQ(write_file(dir.file("cube.mdl"), test::write_mdl(cube_mdl())), "");
    ToolRun run = run_mdltool({"adjacency", dir.file("cube.mdl")});
    EXPECT_EQ(run.exit_code, 0) << run.err;
    // tris 12, nothing dropped, 16 welds, 0 apart, 0 flips, 0 splits, 18 edges, 0 boundary.
    EXPECT_TRUE(
        contains(run.out, "cube.mdl        12     0    0    16     0    0     0     18     0"))
        << run.out;
    EXPECT_TRUE(contains(run.out, "  true\n"));
    run = run_mdltool({"adjacency", "--json", dir.file("cube.mdl")});
    EXPECT_TRUE(contains(run.out, "\"welds\": 16,"));
    EXPECT_TRUE(contains(run.out, "\"mesh_vertices\": 8,"));
    EXPECT_TRUE(contains(run.out, "\"style\": \"true_edges\""));
}

TEST(MdltoolAdjacency, MalformedModelIsReportedAndTheFolderStillRuns) {
    TempDir dir;
    ASSERT_EQ(write_file(dir.file("cube.mdl"), test::write_mdl(cube_mdl())), "");
    ASSERT_EQ(write_file(dir.file("BAD.mdl"), test::write_mdl(bad_mdl())), "");
    ToolRun run = run_mdltool({"adjacency", dir.path()});
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_TRUE(contains(run.err, "BAD.mdl: offset " + std::to_string(kBadOffset) +
                                      ": triangle 1 vertex 2 index 9 is out of range"))
        << run.err;
    EXPECT_TRUE(contains(run.out, "cube.mdl ")) << run.out;
    run = run_mdltool({"adjacency", "--json", dir.path()});
    EXPECT_EQ(run.exit_code, 1);
    ASSERT_TRUE(looks_like_json_object(run.out)) << run.out;
    EXPECT_EQ(count_of(run.out, "\"ok\": false"), 1u);
    EXPECT_TRUE(contains(run.out, "\"offset\": " + std::to_string(kBadOffset)));
    EXPECT_TRUE(contains(run.out, "\"failed\": 1"));
}

TEST(MdltoolAdjacency, ReadsModelsInsideAPak) {
    TempDir dir;
    const auto cube = test::write_mdl(cube_mdl());
    const auto bad = test::write_mdl(bad_mdl());
    const std::string pak = dir.file("pak0.pak");
    ASSERT_EQ(write_file(pak, test::build_pak({{"progs/cube.mdl", {cube.begin(), cube.end()}},
                                               {"progs/bad.mdl", {bad.begin(), bad.end()}},
                                               {"readme.txt", "hi"}})),
              "");
    const ToolRun run = run_mdltool({"adjacency", "--json", pak});
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_TRUE(contains(run.out, "\"path\": \"" + pak + ":progs/cube.mdl\"")) << run.out;
    EXPECT_TRUE(contains(run.err, pak + ":progs/bad.mdl: offset " + std::to_string(kBadOffset)))
        << run.err;
    EXPECT_FALSE(contains(run.out + run.err, "readme"));

    const ToolRun empty = run_mdltool({"adjacency", dir.file("none.pak")});
    EXPECT_EQ(empty.exit_code, 1);
    EXPECT_TRUE(contains(empty.err, "none.pak: no such file or directory")) << empty.err;
}

TEST(MdltoolAdjacency, TimeReportsTheTotal) {
    const ToolRun run = run_mdltool({"adjacency", "--time", progs_dir() + "/gib1.mdl"});
    EXPECT_EQ(run.exit_code, 0);
    EXPECT_TRUE(contains(run.out, "time: weld + adjacency for 1 models ")) << run.out;
    EXPECT_TRUE(contains(run.out, "paper ms/frame"));
}

TEST(MdltoolAdjacency, BadCommandLinesExitWith2) {
    for (const auto& args : std::vector<std::vector<std::string>>{
             {"adjacency"}, {"adjacency", "--json"}, {"adjacency", "--frob", progs_dir()}}) {
        const ToolRun run = run_mdltool(args);
        EXPECT_EQ(run.exit_code, 2) << args.back();
        EXPECT_TRUE(contains(run.err, "usage: mdltool adjacency")) << run.err;
        EXPECT_EQ(run.out, "");
    }
    const ToolRun help = run_mdltool({"--help"});
    EXPECT_TRUE(contains(help.out, "adjacency [--json] [--time] FILE|DIR|PAK..."));
    EXPECT_TRUE(contains(help.out, "export FILE [--frame N | --all-frames]"));
}

TEST(MdltoolExport, WritesTheWeldedMeshOfAFrame) {
    TempDir dir;
    ASSERT_EQ(write_file(dir.file("cube.mdl"), test::write_mdl(cube_mdl())), "");
    const ToolRun run =
        run_mdltool({"export", dir.file("cube.mdl"), "--frame", "1", "-o", dir.file("c.obj")});
    EXPECT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(run.out, dir.file("c.obj") + "\n");
    const std::string obj = slurp(dir.file("c.obj"));
    EXPECT_EQ(lines_starting_with(obj, "v "), 8u) << obj;  // welded: 8 corners, not 24
    EXPECT_EQ(lines_starting_with(obj, "f "), 12u);
    // Frame 1 is moved by 100 in x.
    EXPECT_TRUE(contains(obj, "v 120.000000 20.000000 20.000000\n")) << obj;
    EXPECT_FALSE(contains(obj, "v 20.000000 20.000000 20.000000\n"));
    EXPECT_GE(lines_starting_with(obj, "vt "), 4u);  // the file's texture coordinates
    EXPECT_TRUE(contains(obj, "f 1/"));
}

TEST(MdltoolExport, AllFramesAndOtherFormats) {
    TempDir dir;
    ASSERT_EQ(write_file(dir.file("cube.mdl"), test::write_mdl(cube_mdl())), "");
    ToolRun run =
        run_mdltool({"export", dir.file("cube.mdl"), "--all-frames", "-o", dir.file("c.ply")});
    EXPECT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(run.out, dir.file("c_000.ply") + "\n" + dir.file("c_001.ply") + "\n");
    const std::string ply = slurp(dir.file("c_001.ply"));
    EXPECT_TRUE(contains(ply, "element vertex 8\n")) << ply;
    EXPECT_TRUE(contains(ply, "element face 12\n"));
    // Default output: the model's name with .obj, in the current directory; .off works too.
    run = run_mdltool({"export", dir.file("cube.mdl")}, dir.path());
    EXPECT_EQ(run.exit_code, 0) << run.err;
    EXPECT_TRUE(fs::exists(dir.file("cube.obj")));
    run = run_mdltool({"export", dir.file("cube.mdl"), "-o", dir.file("c.off")});
    EXPECT_EQ(slurp(dir.file("c.off")).rfind("OFF\n8 12 0\n", 0), 0u) << slurp(dir.file("c.off"));
}

TEST(MdltoolExport, ErrorsAreClear) {
    TempDir dir;
    ASSERT_EQ(write_file(dir.file("cube.mdl"), test::write_mdl(cube_mdl())), "");
    ASSERT_EQ(write_file(dir.file("bad.mdl"), test::write_mdl(bad_mdl())), "");
    ToolRun run =
        run_mdltool({"export", dir.file("cube.mdl"), "--frame", "5", "-o", dir.file("x.obj")});
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_TRUE(contains(run.err, "no frame 5 (the model has 2)")) << run.err;
    run = run_mdltool({"export", dir.file("bad.mdl"), "-o", dir.file("x.obj")});
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_TRUE(contains(run.err, "index 9 is out of range")) << run.err;
    for (const auto& args : std::vector<std::vector<std::string>>{
             {"export"},
             {"export", dir.file("cube.mdl"), "-o", dir.file("x.stl")},
             {"export", dir.file("cube.mdl"), "--frame", "1", "--all-frames"},
             {"export", dir.file("cube.mdl"), "--frame", "x"}}) {
        run = run_mdltool(args);
        EXPECT_EQ(run.exit_code, 2) << args.back();
        EXPECT_TRUE(contains(run.err, "usage: mdltool export")) << run.err;
    }
}

}  // namespace
}  // namespace nq

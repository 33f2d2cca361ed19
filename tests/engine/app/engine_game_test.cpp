// Playing the game through the engine binary, headless, driven by a script of ordinary console
// commands: a recorded session is a well-formed protocol 666 demo, the same script records the
// same bytes again (fixed frame time, seeded server), the recording replays in the engine with
// the frame count Quake's playback rule gives for its blocks, and a missing map is a message,
// not a crash.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <regex>

#include "common/file_io.h"
#include "support/engine_image_checks.h"
#include "support/engine_output_checks.h"
#include "formats/bsp.h"
#include "formats/dem.h"
#include "formats/entities.h"
#include "formats/message_decoder.h"
#include "support/engine_run.h"
#include "support/test_data.h"

namespace nq {
namespace {

using namespace test;

// 2 s of walking forward, a turn, a second of running while firing.
std::string walk_script(const std::string& demo) {
    std::string s = "host_framerate 0.0138889\nrecord " + demo + " start\n";
    auto wait = [&](int frames) {
        for (int i = 0; i < frames; ++i) s += "wait\n";
    };
    wait(10);
    s += "+forward\n";
    wait(144);
    s += "viewpos\n-forward\n+right\n";
    wait(40);
    s += "viewpos\n-right\n+forward\n+attack\n";
    wait(36);
    s += "viewpos\n";
    wait(36);
    s += "viewpos\n-forward\n-attack\nstop\nquit\n";
    return s;
}

struct Recording {
    ProcessResult run;
    std::vector<uint8_t> demo;
};

Recording record(const TempDir& dir, const std::string& name) {
    const std::string user = dir.subdir("user_" + name);
    const std::string game_dir = user + "/lq1";
    std::filesystem::create_directories(game_dir);
    std::ofstream(game_dir + "/walk.cfg") << walk_script(name);
    Recording r;
    r.run = run_nprquake({"-userdir", user, "-basedir", data_root(), "-game", "lq1", "-width",
                          "320", "-height", "240", "+exec", "walk.cfg"},
                         dir.path(), 300);
    if (auto bytes = read_file(game_dir + "/" + name + ".dem")) r.demo = std::move(*bytes);
    return r;
}

// Frames a timedemo reports for `demo`, by Quake's rule: the first frame reads every block up
// to the first entity update after signon stage 3, and one more; each later frame reads one
// block; the frame that reads the disconnect is not played, and the first is not counted.
uint64_t expected_timedemo_frames(const Demo& demo) {
    protocol::ProtocolState state;
    bool stage3 = false;
    size_t first_frame_end = 0;
    for (size_t i = 0; i < demo.blocks.size() && first_frame_end == 0; ++i) {
        auto block = decode_server_message(demo.blocks[i].message, {"rec", i, 0}, state);
        if (!block) return 0;
        for (const DecodedMessage& m : block->messages) {
            if (auto* s = std::get_if<svc::SignonNum>(&m.message)) stage3 = s->stage == 3;
            if (stage3 && std::holds_alternative<svc::EntityUpdate>(m.message)) {
                first_frame_end = i + 1;
            }
        }
    }
    if (first_frame_end == 0 || demo.blocks.size() < first_frame_end + 2) return 0;
    return demo.blocks.size() - first_frame_end - 2;
}

TEST(EngineGame, ScriptedSessionRecordsAReplayableDeterministicDemo) {
    TempDir dir("nq_game");
    const Recording a = record(dir, "walk_a");
    ASSERT_EQ(a.run.exit_code, 0) << a.run.describe();
    EXPECT_EQ(sanitizer_report(a.run.err), "");
    ASSERT_FALSE(a.demo.empty()) << a.run.out;

    // A well-formed demo: every block decodes under protocol 666; the player moved.
    auto demo = parse_dem(a.demo, "walk_a.dem");
    ASSERT_TRUE(demo) << demo.error().to_string();
    protocol::ProtocolState state;
    std::optional<Vec3> first_origin, last_origin;
    int disconnects = 0;
    for (size_t i = 0; i < demo->blocks.size(); ++i) {
        auto block = decode_server_message(demo->blocks[i].message, {"walk_a.dem", i, 0}, state);
        ASSERT_TRUE(block) << block.error().to_string();
        for (const DecodedMessage& m : block->messages) {
            if (auto* u = std::get_if<svc::EntityUpdate>(&m.message); u && u->entity == 1) {
                if (!first_origin) first_origin = u->origin;
                last_origin = u->origin;
            }
            disconnects += std::holds_alternative<svc::Disconnect>(m.message);
        }
    }
    EXPECT_EQ(state.protocol, protocol::kFitzQuake);
    EXPECT_EQ(disconnects, 1);
    ASSERT_TRUE(first_origin && last_origin);
    const float moved =
        std::hypot((*last_origin)[0] - (*first_origin)[0], (*last_origin)[1] - (*first_origin)[1]);
    EXPECT_GT(moved, 100.0f) << "the player should have walked";

    // Same script, same frame time, same seed: the same bytes.
    const Recording b = record(dir, "walk_b");
    ASSERT_EQ(b.run.exit_code, 0) << b.run.describe();
    EXPECT_EQ(a.demo, b.demo) << "two recordings of one script differ";

    // It replays here with the frame count its blocks give, and the player where the game had
    // him: every position the game printed is the replay's at the same server time.
    const std::string user = dir.path() + "/user_walk_a";
    ProcessResult replay =
        run_nprquake({"-userdir", user, "-basedir", data_root(), "-game", "lq1", "-width", "320",
                      "-height", "240", "+alias", "everyframe", "viewpos; wait; everyframe",
                      "+demo_at", "1", "everyframe", "+timedemo", "walk_a", "+quit"},
                     dir.path(), 300);
    ASSERT_EQ(replay.exit_code, 0) << replay.describe();
    const auto lines = timedemo_lines(replay.out);
    ASSERT_EQ(lines.size(), 1u) << replay.out;
    EXPECT_EQ(lines[0].frames, expected_timedemo_frames(*demo));

    const auto positions = [](const std::string& out) {
        std::map<std::string, std::string> at;  // time -> origin
        const std::regex line(R"(viewpos: time (\S+) origin (.+))");
        for (const std::string& text : lines_containing(out, "viewpos: time")) {
            std::smatch m;
            if (std::regex_search(text, m, line)) at.emplace(m[1].str(), m[2].str());
        }
        return at;
    };
    const auto played = positions(a.run.out);
    const auto replayed = positions(replay.out);
    ASSERT_EQ(played.size(), 4u) << a.run.out;
    ASSERT_GT(replayed.size(), 200u);
    for (const auto& [time, origin] : played) {
        ASSERT_TRUE(replayed.count(time)) << "the replay never showed server time " << time;
        EXPECT_EQ(replayed.at(time), origin) << "at server time " << time;
    }
}

TEST(EngineGame, MissingMapIsAMessageAndTheEngineGoesOn) {
    TempDir dir("nq_game_missing");
    ProcessResult r = run_nprquake(
        {"-userdir", dir.subdir("user"), "-basedir", data_root(), "-game",     "lq1",  "-width",
         "320",      "-height",          "240",      "+map",      "nosuchmap", "+map", "start",
         "+wait",    "+changelevel",     "e1m2",     "+wait",     "+status",   "+quit"},
        dir.path(), 120);
    ASSERT_EQ(r.exit_code, 0) << r.describe();
    EXPECT_FALSE(lines_containing(r.out, "maps/nosuchmap.bsp").empty()) << r.out;
    // A changelevel (what lq1m1's exit asks for) to a map that is not there leaves the game on.
    EXPECT_FALSE(lines_containing(r.out, "maps/e1m2.bsp; the game goes on").empty()) << r.out;
    EXPECT_FALSE(lines_containing(r.out, "map: start").empty()) << r.out;
}

// The centre of lq1m1's trigger_changelevel (its brush model's box, from the map's own
// lumps) and the map it names.
struct LevelExit {
    std::array<float, 3> centre{};
    std::string map;
};

std::optional<LevelExit> lq1m1_exit() {
    auto bytes = read_file(lq1_dir() + "/maps/lq1m1.bsp");
    if (!bytes) return std::nullopt;
    auto bsp = parse_bsp(*bytes, "lq1m1.bsp");
    if (!bsp) return std::nullopt;
    auto entities = parse_entities(bsp->entities, "lq1m1.bsp");
    if (!entities) return std::nullopt;
    for (const Entity& e : entities->entities) {
        if (find_value(e, "classname") != "trigger_changelevel") continue;
        const auto model = find_value(e, "model");
        const auto map = find_value(e, "map");
        if (!model || !map || model->size() < 2 || (*model)[0] != '*') continue;
        const size_t index = std::stoul(std::string(model->substr(1)));
        if (index >= bsp->models.size()) continue;
        const BspModel& m = bsp->models[index];
        LevelExit out;
        for (int k = 0; k < 3; ++k) out.centre[size_t(k)] = (m.mins[k] + m.maxs[k]) / 2;
        out.map = std::string(*map);
        return out;
    }
    return std::nullopt;
}

// A player walking into lq1m1's exit sees the intermission; pressing fire after it asks for
// the next map, which is not in the data: a message, and the game goes on on lq1m1.
TEST(EngineGame, TheExitToAMissingMapIsAMessageAndTheLevelGoesOn) {
    const std::optional<LevelExit> exit = lq1m1_exit();
    ASSERT_TRUE(exit) << "lq1m1 has no trigger_changelevel with a brush model";
    ASSERT_FALSE(std::filesystem::exists(lq1_dir() + "/maps/" + exit->map + ".bsp"))
        << "the test needs an exit to a map that is not there";
    TempDir dir("nq_game_exit");
    const std::string user = dir.subdir("user");
    std::filesystem::create_directories(user + "/lq1");
    std::string script = "host_framerate 0.0138889\nmap lq1m1\ngod\nnotarget\n";
    auto wait = [&](int n) {
        for (int i = 0; i < n; ++i) script += "wait\n";
    };
    wait(10);
    char setpos[128];
    std::snprintf(setpos, sizeof setpos, "setpos %.1f %.1f %.1f\n", double(exit->centre[0]),
                  double(exit->centre[1]), double(exit->centre[2]));
    script += setpos;
    wait(72 * 7);  // the intermission, then Quake's 5 s before a button may end it
    for (int press = 0; press < 4; ++press) {
        script += "+attack\n";
        wait(36);
        script += "-attack\n";
        wait(36);
    }
    script += "status\nquit\n";
    std::ofstream(user + "/lq1/exit.cfg") << script;
    ProcessResult r =
        run_nprquake({"-userdir", user, "-basedir", data_root(), "-game", "lq1", "-width", "160",
                      "-height", "120", "+r_plugin", "null", "+exec", "exit.cfg"},
                     dir.path(), 300);
    ASSERT_EQ(r.exit_code, 0) << r.describe();
    EXPECT_EQ(sanitizer_report(r.out + r.err), "");
    EXPECT_FALSE(lines_containing(r.out, "maps/" + exit->map + ".bsp; the game goes on").empty())
        << r.out;
    EXPECT_FALSE(lines_containing(r.out, "map: lq1m1").empty()) << r.out;
}

// The game goes on through plugin swaps: the server clock keeps advancing and each style
// draws the level (technical's white faces and dark lines, illustrative's ramp-shaded weapon
// and abstracted textures differ from classic's).
TEST(EngineGame, SwappingStylesMidGameKeepsItRunningAndDrawn) {
    TempDir dir("nq_game_swap");
    const std::string user = dir.subdir("user");
    std::filesystem::create_directories(user + "/lq1");
    const std::vector<std::string> styles = {"classic", "technical", "illustrative", "classic"};
    // (The last classic picture is not compared with the first: 90 frames of a running level
    // change more pixels than a style does on a still view.)
    std::string script = "host_framerate 0.0138889\nmap start\n";
    auto wait = [&](int n) {
        for (int i = 0; i < n; ++i) script += "wait\n";
    };
    for (size_t i = 0; i < styles.size(); ++i) {
        if (i > 0) script += "r_plugin " + styles[i] + "\n";
        wait(30);
        script += "screenshot " + dir.file(std::to_string(i) + ".png") + "\nstatus\n";
    }
    script += "quit\n";
    std::ofstream(user + "/lq1/swap.cfg") << script;
    ProcessResult r = run_nprquake({"-userdir", user, "-basedir", data_root(), "-game", "lq1",
                                    "-width", "320", "-height", "240", "+exec", "swap.cfg"},
                                   dir.path(), 300);
    ASSERT_EQ(r.exit_code, 0) << r.describe();
    EXPECT_EQ(sanitizer_report(r.err), "");
    // A status report per style, the server clock advancing 30 frames (30/72 s) between them.
    std::vector<double> times;
    for (const std::string& line : lines_containing(r.out, "time: ")) {
        times.push_back(std::stod(line.substr(line.find("time: ") + 6)));
    }
    ASSERT_EQ(times.size(), styles.size()) << r.out;
    // `status` prints the time to 0.1 s, so each difference is known to within 0.1 s.
    for (size_t i = 1; i < times.size(); ++i) {
        EXPECT_NEAR(times[i] - times[i - 1], 30.0 / 72, 0.1) << styles[i];
    }
    EXPECT_NEAR(times.back() - times.front(), 30.0 * double(times.size() - 1) / 72, 0.1);
    EXPECT_EQ(lines_containing(r.out, "renderer: technical").size(), 1u);
    EXPECT_EQ(lines_containing(r.out, "renderer: illustrative").size(), 1u);
    std::vector<RgbImage> shots(styles.size());
    for (size_t i = 0; i < styles.size(); ++i) {
        ASSERT_NO_FATAL_FAILURE(
            test::load_screenshot(dir.file(std::to_string(i) + ".png"), shots[i]));
        ASSERT_EQ(shots[i].width, shots[0].width);
        ASSERT_EQ(shots[i].height, shots[0].height);
        const test::RegionStats stats = test::region_stats(shots[i], test::whole(shots[i]));
        EXPECT_GT(stats.distinct_colours, 50u) << styles[i] << " drew nothing";
    }
    // Same place, 30 frames apart, a still player: what differs from classic is the style.
    auto share_differing = [&](const RgbImage& a, const RgbImage& b) {
        size_t differing = 0;
        for (int y = 0; y < a.height; ++y) {
            for (int x = 0; x < a.width; ++x) {
                differing += !test::near_colour(test::pixel(a, x, y), test::pixel(b, x, y), 40);
            }
        }
        return double(differing) / double(a.width * a.height);
    };
    EXPECT_GT(share_differing(shots[0], shots[1]), 0.005) << "technical looks like classic";
    EXPECT_GT(share_differing(shots[0], shots[2]), 0.005) << "illustrative looks like classic";
}

}  // namespace
}  // namespace nq

// Quake's start-up with a game directory that has a quake.rc (LibreQuake's): `exec quake.rc`
// runs default.cfg, config.cfg and autoexec.cfg, then `stuffcmds` the command line's
// +commands, then `startdemos`, whose demos that are not here only warn. Started without a
// +command, the engine shows the main menu over the demo loop. Facts come from the data
// itself: quake.rc's startdemos line, which demo files exist, gfx/mainmenu.lmp's texels.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/file_io.h"
#include "support/engine_image_checks.h"
#include "formats/lmp.h"
#include "formats/palette.h"
#include "support/engine_run.h"
#include "support/test_data.h"

namespace nq {
namespace {

using namespace test;

// The names after `startdemos` in the game's quake.rc.
std::vector<std::string> startdemos_names() {
    std::ifstream in(lq1_dir() + "/quake.rc");
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream words(line);
        std::string word;
        words >> word;
        if (word != "startdemos") continue;
        std::vector<std::string> names;
        while (words >> word) names.push_back(word);
        return names;
    }
    return {};
}

bool demo_file_exists(const std::string& name) {
    return std::filesystem::exists(lq1_dir() + "/" + name + ".dem");
}

void write_text(const std::string& path, const std::string& text) {
    std::filesystem::create_directories(std::filesystem::path(path).parent_path());
    std::ofstream(path) << text;
}

size_t position_of(const std::string& text, const std::string& needle) {
    const size_t at = text.find(needle);
    EXPECT_NE(at, std::string::npos) << "no \"" << needle << "\" in the output";
    return at;
}

TEST(EngineStartup, QuakeRcRunsTheConfigsThenTheCommandLineThenTheDemoLoop) {
    const std::vector<std::string> listed = startdemos_names();
    ASSERT_FALSE(listed.empty()) << "the data's quake.rc has no startdemos line";
    TempDir dir;
    const std::string user = dir.subdir("user");
    // autoexec.cfg runs after default.cfg: LibreQuake's binding of w is in place by then.
    write_text(user + "/lq1/autoexec.cfg", "bind w\necho autoexec_ran\n");
    ProcessResult r =
        run_nprquake({"-userdir", user, "-basedir", data_root(), "-game", "lq1", "-width", "160",
                      "-height", "120", "+echo", "plus_ran", "+quit"},
                     dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.describe();
    EXPECT_EQ(sanitizer_report(r.out + r.err), "");
    const size_t rc = position_of(r.out, "execing quake.rc");
    const size_t defaults = position_of(r.out, "execing default.cfg");
    const size_t bound = position_of(r.out, "\"w\" = \"+forward\"");
    const size_t autoexec = position_of(r.out, "autoexec_ran");
    const size_t plus = position_of(r.out, "plus_ran");
    EXPECT_LT(rc, defaults);
    EXPECT_LT(defaults, bound);
    EXPECT_LT(bound, autoexec);
    EXPECT_LT(autoexec, plus);
    size_t present = 0;
    for (const std::string& name : listed) {
        const std::string warning = "startdemos: " + name + " is not here, skipped";
        if (demo_file_exists(name)) {
            ++present;
            EXPECT_EQ(r.out.find(warning), std::string::npos) << warning;
        } else {
            EXPECT_GT(position_of(r.out, warning), plus);
        }
    }
    if (present > 0) {
        EXPECT_NE(r.out.find(std::to_string(present) + " demo(s) in loop"), std::string::npos);
    }
    // +quit came first: the loop was set but never started.
    EXPECT_EQ(r.out.find("FITZQUAKE"), std::string::npos) << "a demo started after +quit";
}

TEST(EngineStartup, WithoutPlusCommandsTheMainMenuShowsOverTheDemoLoop) {
    TempDir dir;
    const std::string user = dir.subdir("user");
    const std::string shot = dir.file("menu.png");
    // No +command: the screenshot is scheduled from autoexec.cfg, on the loop's demo.
    write_text(user + "/lq1/autoexec.cfg",
               "con_notifytime 0\ndemo_at 30 \"screenshot " + shot + "; quit\"\n");
    ProcessResult r = run_nprquake({"-userdir", user, "-basedir", data_root(), "-game", "lq1",
                                    "-width", "320", "-height", "240"},
                                   dir.path(), 300);
    ASSERT_EQ(r.exit_code, 0) << r.describe() << "\nstdout tail:\n"
                              << r.out.substr(r.out.size() > 3000 ? r.out.size() - 3000 : 0);
    ASSERT_FALSE(r.timed_out);
    EXPECT_NE(r.out.find("demo(s) in loop"), std::string::npos) << r.out;
    RgbImage image;
    ASSERT_NO_FATAL_FAILURE(load_screenshot(shot, image));

    // The menu canvas at 320x240: scale 1 (default.cfg's scr_menuscale 5, limited to fit),
    // centred vertically: top 20. mainmenu.lmp at (72, 32).
    auto bytes = read_file(lq1_dir() + "/gfx/mainmenu.lmp");
    ASSERT_TRUE(bytes);
    auto items = parse_qpic(*bytes, "mainmenu.lmp");
    ASSERT_TRUE(items);
    auto palette_bytes = read_file(lq1_dir() + "/gfx/palette.lmp");
    ASSERT_TRUE(palette_bytes);
    auto palette = parse_palette(*palette_bytes, "palette.lmp");
    ASSERT_TRUE(palette);
    int checked = 0, matched = 0;
    for (int y = 1; y + 1 < items->height; ++y) {
        for (int x = 1; x + 1 < items->width; ++x) {
            const uint8_t index = items->at(x, y);
            if (index == 255) continue;
            const int sx = 72 + x, sy = 20 + 32 + y;
            const uint8_t* p = &image.rgb[(size_t(sy) * size_t(image.width) + size_t(sx)) * 3];
            const auto want = palette->colors[index];
            ++checked;
            if (std::abs(p[0] - want.r) <= 3 && std::abs(p[1] - want.g) <= 3 &&
                std::abs(p[2] - want.b) <= 3) {
                ++matched;
            }
        }
    }
    ASSERT_GT(checked, 1000);
    // Every opaque texel is on screen as its palette colour (the menu is drawn texel for texel).
    EXPECT_GE(matched, checked * 99 / 100) << matched << " of " << checked;
}

// A game directory over the real data whose map (the one the demos play on) is cut in half:
// <base>/id1 is the data's lq1, <base>/broken holds the damaged map and its own quake.rc.
struct BrokenLevelGame {
    explicit BrokenLevelGame(const TempDir& dir, const std::string& quake_rc)
        : base(dir.subdir("base")), user(dir.subdir("user")) {
        std::filesystem::create_directory_symlink(lq1_dir(), base + "/id1");
        auto map = read_file(lq1_dir() + "/maps/start.bsp");
        EXPECT_TRUE(map) << "the demos' map maps/start.bsp is missing";
        std::vector<uint8_t> half;
        if (map) half.assign(map->begin(), map->begin() + std::ptrdiff_t(map->size() / 2));
        std::filesystem::create_directories(base + "/broken/maps");
        EXPECT_EQ(write_file(base + "/broken/maps/start.bsp", half), "");
        write_text(base + "/broken/quake.rc", quake_rc);
    }
    std::vector<std::string> args(std::initializer_list<std::string> more) const {
        std::vector<std::string> a{"-userdir", user, "-basedir", base, "-game", "broken"};
        a.insert(a.end(), {"-width", "160", "-height", "120"});
        a.insert(a.end(), more);
        return a;
    }
    std::string base, user;
};

// Enough frames for a spinning loop to show itself, then an end.
std::string wait_then_quit(int frames) {
    std::string text;
    for (int i = 0; i < frames; ++i) text += "wait\n";
    return text + "echo waited\nquit\n";
}

size_t lines_starting_with(const std::string& text, const std::string& prefix) {
    size_t n = 0;
    for (const std::string& line : lines_containing(text, prefix)) n += line.rfind(prefix, 0) == 0;
    return n;
}

TEST(EngineStartup, ADemoLoopWhoseLevelIsBrokenTriesEachDemoOnceThenStops) {
    ASSERT_TRUE(demo_file_exists("demo") && demo_file_exists("demo2"));
    TempDir dir;
    BrokenLevelGame game(dir, "startdemos demo demo2\n" + wait_then_quit(150));
    ProcessResult r = run_nprquake(game.args({}), dir.path(), 180);
    ASSERT_EQ(r.exit_code, 0) << r.describe();
    EXPECT_EQ(sanitizer_report(r.out + r.err), "");
    EXPECT_NE(r.out.find("2 demo(s) in loop: demo demo2"), std::string::npos) << r.out;
    // One failure per demo, then one message: no retrying while 150 frames go by.
    EXPECT_EQ(lines_starting_with(r.out, "cannot load level: maps/start.bsp"), 2u) << r.out;
    EXPECT_EQ(lines_starting_with(r.out, "demos: no demo of the loop can play"), 1u) << r.out;
    EXPECT_LT(position_of(r.out, "demos: no demo of the loop"), position_of(r.out, "waited"));
}

TEST(EngineStartup, AFailedCommandLineTimedemoLeavesTheDemoLoopOff) {
    TempDir dir;
    BrokenLevelGame game(dir, "stuffcmds\nstartdemos demo demo2\n" + wait_then_quit(150));
    ProcessResult r = run_nprquake(game.args({"+timedemo", "demo"}), dir.path(), 180);
    EXPECT_EQ(r.exit_code, 1) << "the command line's timedemo failed\n" << r.describe();
    EXPECT_EQ(sanitizer_report(r.out + r.err), "");
    EXPECT_EQ(lines_starting_with(r.out, "timedemo demo failed (no frame rate reported)"), 1u)
        << r.out;
    // quake.rc's startdemos ran after it (it waited for the demo) and kept the loop off.
    EXPECT_LT(position_of(r.out, "timedemo demo failed"), position_of(r.out, "demo(s) in loop"));
    EXPECT_EQ(lines_starting_with(r.out, "cannot load level: maps/start.bsp"), 1u) << r.out;
    EXPECT_NE(r.out.find("waited"), std::string::npos) << r.out;
}

TEST(EngineStartup, AFailedCommandLinePlaydemoLeavesTheDemoLoopOff) {
    TempDir dir;
    BrokenLevelGame game(dir, "stuffcmds\nstartdemos demo demo2\n" + wait_then_quit(60));
    ProcessResult r = run_nprquake(game.args({"+playdemo", "nosuchdemo"}), dir.path(), 180);
    ASSERT_EQ(r.exit_code, 0) << r.describe();
    EXPECT_EQ(sanitizer_report(r.out + r.err), "");
    EXPECT_FALSE(lines_containing(r.out, "nosuchdemo").empty()) << r.out;
    EXPECT_NE(r.out.find("demo(s) in loop"), std::string::npos) << r.out;
    // As Quake (its demonum -1): the loop was set and not started, so no demo met the level.
    EXPECT_EQ(lines_starting_with(r.out, "cannot load level"), 0u) << r.out;
    EXPECT_NE(r.out.find("waited"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace nq

// The nprquake runs the engine tests share (see support/shared_engine_run.h): each is made once
// per test session and serves every test that reads its output or screenshots.
//
// All runs are headless (SDL offscreen, llvmpipe), small (320x240) and keep the screen free of
// what the engine draws over the scene: con_notifytime 0 and scr_centertime 0 stop printed
// lines and centre messages, scr_drawhud 0 the status bar and scoreboards and gl_polyblend 0
// the screen tints, so screenshots show only what the renderer drew (engine_hud_test.cpp turns
// the bar back on). The game's quake.rc runs first (LibreQuake's default.cfg turns on the
// crosshair and the fps counter); the +commands come after it, so they win.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "support/build_paths.h"
#include "support/shared_engine_run.h"
#include "support/test_data.h"

namespace nq::test::engine_runs {

inline constexpr int kWidth = 320;
inline constexpr int kHeight = 240;
// Frames of demo.dem the demo runs screenshot: up to 600 the player looks about level around
// the start room; 760 and 860 pass close by the monster gallery, where the model-placement
// test finds its subject.
inline constexpr std::array<uint64_t, 6> kScreenshotFrames = {150, 300, 450, 600, 760, 860};

// Where the alias-only test plugin (tests/plugins/alias_only_plugin.c) is built.
inline std::string alias_only_plugin_dir() {
    return test_plugin_dir() + "/alias_only";
}

// -userdir inside the run (so no config from elsewhere applies), the game data, the size.
inline std::vector<std::string> base_args(const std::string& dir, const std::string& basedir,
                                          const std::string& game) {
    std::vector<std::string> args{"-userdir", dir + "/user", "-basedir", basedir};
    if (!game.empty()) args.insert(args.end(), {"-game", game});
    args.insert(args.end(), {"-width", std::to_string(kWidth), "-height", std::to_string(kHeight),
                             "+con_notifytime", "0", "+scr_centertime", "0", "+scr_drawhud", "0",
                             "+gl_polyblend", "0", "+crosshair", "0", "+scr_showfps", "0"});
    return args;
}

inline void add(std::vector<std::string>& args, std::initializer_list<std::string> more) {
    args.insert(args.end(), more);
}

inline void demo_at(std::vector<std::string>& args, uint64_t frame, const std::string& commands) {
    add(args, {"+demo_at", std::to_string(frame), commands});
}

inline std::string shot(const std::string& dir, const std::string& prefix, uint64_t frame) {
    return dir + "/" + prefix + "_" + std::to_string(frame) + ".png";
}

// `timedemo demo` with the classic renderer, screenshots at kScreenshotFrames; after the last
// one the null renderer plays the rest (nothing left to look at, and it is 4x faster).
inline const SharedRun& demo_classic() {
    return shared_nprquake_run("demo_classic", [](const std::string& dir) {
        auto args = base_args(dir, data_root(), "lq1");
        for (uint64_t f : kScreenshotFrames)
            demo_at(args, f, "screenshot " + shot(dir, "classic", f));
        demo_at(args, kScreenshotFrames.back() + 50, "r_plugin null");
        add(args, {"+timedemo", "demo", "+quit"});
        return args;
    });
}

// The same frames drawn by the alias-only test plugin: only alias models, on black.
inline const SharedRun& demo_alias_only() {
    return shared_nprquake_run("demo_alias_only", [](const std::string& dir) {
        auto args = base_args(dir, data_root(), "lq1");
        add(args, {"-plugindir", alias_only_plugin_dir(), "+r_plugin", "test_alias_only"});
        for (uint64_t f : kScreenshotFrames)
            demo_at(args, f, "screenshot " + shot(dir, "alias", f));
        demo_at(args, kScreenshotFrames.back() + 1, "quit");
        add(args, {"+timedemo", "demo", "+quit"});
        return args;
    });
}

// `timedemo demo2` with renderer swaps on a loaded level: classic -> null at 200 (screenshot
// at 300) -> classic at 400 (screenshot at 600) -> null at 650 (speed) -> classic at 2150, so
// the -benchjson record names classic.
inline constexpr uint64_t kDemo2NullShot = 300;
inline constexpr uint64_t kDemo2ClassicShot = 600;
inline const SharedRun& demo2_swaps() {
    return shared_nprquake_run("demo2_swaps", [](const std::string& dir) {
        auto args = base_args(dir, data_root(), "lq1");
        add(args, {"-benchjson", dir + "/bench.jsonl"});
        demo_at(args, 200, "r_plugin null");
        demo_at(args, kDemo2NullShot, "screenshot " + shot(dir, "null", kDemo2NullShot));
        demo_at(args, 400, "r_plugin classic");
        demo_at(args, kDemo2ClassicShot, "screenshot " + shot(dir, "classic", kDemo2ClassicShot));
        demo_at(args, 650, "r_plugin null");
        demo_at(args, 2150, "r_plugin classic");
        add(args, {"+timedemo", "demo2", "+quit"});
        return args;
    });
}

}  // namespace nq::test::engine_runs

// The engine's console commands: demos, renderer plugins, screenshots, showroom (the timedemo
// wing reports and measures; app/timedemo).
#include <epoxy/gl.h>

#include <cstdio>
#include <filesystem>

#include "app/engine.h"
#include "host/number_text.h"
#include "video/screenshot.h"

namespace nq {

void Engine::register_commands() {
    CommandSystem& c = host_.commands();
    c.add_command(
        "quit", [this](const CommandArgs&) { quit_ = true; }, "leave the engine");
    c.add_command(
        "playdemo",
        [this](const CommandArgs& a) {
            if (a.argc() < 2) return print("usage: playdemo <demo>");
            start_demo(a.argv(1), DemoMode::Playback);
        },
        "play a demo in recorded time");
    c.add_command(
        "timedemo",
        [this](const CommandArgs& a) {
            if (a.argc() < 2) return print("usage: timedemo <demo>");
            start_demo(a.argv(1), DemoMode::TimeDemo);
        },
        "play a demo as fast as possible and report the frame rate");
    c.add_command(
        "stop",
        [this](const CommandArgs&) {
            if (!game_->stop_recording()) end_demo();
        },
        "stop recording a demo (or, when none is recorded, the demo being played)");
    c.add_command(
        "pause", [this](const CommandArgs& a) { pause_demo(a); },
        "freeze the demo being played (pause [0|1]; no argument toggles)");
    c.add_command(
        "viewpos", [this](const CommandArgs&) { print_view_position(); },
        "the player's position as the last message gave it, with that message's server time");
    c.add_command(
        "screenshot",
        [this](const CommandArgs& a) { screenshot(a.argc() > 1 ? a.argv(1) : std::string()); },
        "save the screen as PNG (screenshot [file.png])");
    c.add_command(
        "vo_dump_scene",
        [this](const CommandArgs& a) {
            if (a.argc() < 2) return print("usage: vo_dump_scene <file>");
            frames_->dispatch().dump_scene_next_frame(a.argv(1),
                                                      [this](const std::string& m) { print(m); });
        },
        "write the next frame's geometry for the ray-traced obscurance reference (vo_reference)");
    c.add_command(
        "r_plugin",
        [this](const CommandArgs& a) {
            if (a.argc() < 2) {
                return print("renderer: " + frames_->plugins().active_name() +
                             " (r_plugins lists the others)");
            }
            swap_plugin(a.argv(1));
        },
        "load a renderer plugin by name, replacing the current one");
    c.add_command(
        "r_plugins",
        [this](const CommandArgs&) {
            for (const auto& p : frames_->plugins().available()) {
                print((p.name == frames_->plugins().active_name() ? "* " : "  ") + p.name + "  " +
                      p.path);
            }
        },
        "list renderer plugins");
    c.add_command(
        "showroom",
        [this](const CommandArgs&) {
            if (demo_->active()) end_demo();
            frames_->show_showroom(true);
        },
        "show the built-in showroom scene");
    c.add_command(
        "path",
        [this](const CommandArgs&) {
            if (!vfs_) return print("no game data mounted");
            for (const auto& p : vfs_->search_paths()) print(p.describe());
        },
        "show the search path");
}

// Quake's viewpos, from the messages themselves (not the interpolated view), so a game and
// the replay of its recording can be compared exactly: "viewpos: time T origin X Y Z".
void Engine::print_view_position() {
    if (!demo_->active()) return print("viewpos: no game or demo is running");
    const ClientState& client = demo_->client();
    const ClientEntity* player = client.entity(client.view_entity());
    if (!player || player->msg_time < 0) return print("viewpos: no position yet");
    const Vec3& o = player->msg_origins[0];
    char line[128];
    std::snprintf(line, sizeof line, "viewpos: time %.4f origin %.3f %.3f %.3f", player->msg_time,
                  double(o[0]), double(o[1]), double(o[2]));
    print(line);
}

void Engine::swap_plugin(const std::string& name) {
    std::string why = frames_->load_plugin(name);
    if (!why.empty()) {
        std::string current = frames_->plugins().active_name();
        print("r_plugin: " + why + (current.empty() ? "" : "; keeping " + current));
        return;
    }
    host_.cvars().set(*cvars_.r_plugin, name);
    print("renderer: " + frames_->plugins().active_name());
    frames_->warm_up_shown_level(demo_->level(), frame_settings());
}

void Engine::start_demo(const std::string& name, DemoMode mode) {
    timedemo_.demo_requested();
    std::string why = demo_->start(name, mode);
    if (!why.empty()) {
        if (mode != DemoMode::TimeDemo) return print(why);
        TimedemoRun run = describe_run();
        run.demo = name;
        return timedemo_.timedemo_failed(run, why);
    }
    frames_->show_showroom(false);
    demo_loop_.set_playing(false);  // a demo chosen by hand ends the attract loop
    // The rest of the command line ("+timedemo demo +quit") waits for the demo to end.
    timedemo_.demo_started();
}

void Engine::end_demo() {
    if (!demo_->active()) return;
    const bool timedemo = demo_->mode() == DemoMode::TimeDemo && !demo_->live();
    if (timedemo) timedemo_.finish_timedemo(describe_run());
    demo_->stop();
    demo_loop_.set_playing(false);
    if (!vfs_) frames_->show_showroom(true);
    timedemo_.demo_ended(timedemo, quit_);
}

void Engine::begin_game(std::unique_ptr<LiveGame> game, const std::string& map) {
    if (demo_->active()) end_demo();
    frames_->show_showroom(false);
    demo_->start_game(std::move(game), map);
}

void Engine::pause_demo(const CommandArgs& args) {
    if (!demo_->active()) return print("pause: no demo is playing");
    bool on = !demo_->paused();
    if (args.argc() > 1) on = parse_number_prefix(args.argv(1)) != 0;
    demo_->set_paused(on);
    print(on ? "paused" : "unpaused");
}

TimedemoRun Engine::describe_run() const {
    TimedemoRun run;
    run.demo = demo_->name();
    run.failure = demo_->failure();
    // A run that failed at start-up failed before the plugin loaded: the one it was to use.
    run.plugin =
        frames_->plugins().active() ? frames_->plugins().active_name() : cvars_.r_plugin->string();
    run.width = screen_->width();
    run.height = screen_->height();
    run.gl_renderer = screen_->gl_info().renderer;
    run.gl_version = screen_->gl_info().version;
    return run;
}

void Engine::screenshot(const std::string& name) {
    std::string path = name;
    if (path.empty()) {
        std::string dir = user_dir() + "/" + options_.game.value_or("id1");
        std::error_code ec;
        std::filesystem::create_directories(dir, ec);
        auto next = next_screenshot_path(dir);
        if (!next) return print("screenshot: " + next.error().message);
        path = next.value();
    }
    std::string error = save_screenshot(path, 0, screen_->width(), screen_->height());
    print(error.empty() ? "wrote " + path : "screenshot: " + error);
}

}  // namespace nq

// The shell's console commands: quit, renderer plugins, screenshots, the showroom, the search
// path (demos and games are the sessions wing's, app/sessions; timedemo's, app/timedemo).
#include <epoxy/gl.h>

#include <cstdio>
#include <filesystem>

#include "app/engine.h"
#include "video/screenshot.h"

namespace nq {

void Engine::register_commands() {
    CommandSystem& c = host_.commands();
    c.add_command(
        "quit", [this](const CommandArgs&) { quit_ = true; }, "leave the engine");
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
            sessions_->end_demo();
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

void Engine::swap_plugin(const std::string& name) {
    std::string why = frames_->load_plugin(name);
    if (!why.empty()) {
        std::string current = frames_->plugins().active_name();
        print("r_plugin: " + why + (current.empty() ? "" : "; keeping " + current));
        return;
    }
    host_.cvars().set(*cvars_.r_plugin, name);
    print("renderer: " + frames_->plugins().active_name());
    frames_->warm_up_shown_level(sessions_->session().level(), frame_settings());
}

TimedemoRun Engine::describe_renderer() const {
    TimedemoRun run;
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

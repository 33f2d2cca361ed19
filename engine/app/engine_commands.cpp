// The engine's console commands: demos, timedemo, renderer plugins, screenshots, showroom.
#include <epoxy/gl.h>

#include <cstdio>
#include <filesystem>

#include "app/engine.h"
#include "host/number_text.h"
#include "video/bench_record.h"
#include "video/frame_times_file.h"
#include "video/screenshot.h"

namespace nq {

namespace {

std::string format(const char* fmt, double a, double b = 0, double c = 0, double d = 0) {
    char buf[256];
    std::snprintf(buf, sizeof buf, fmt, a, b, c, d);
    return buf;
}

}  // namespace

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
        "demo_at",
        [this](const CommandArgs& a) {
            if (a.argc() < 3) return print("usage: demo_at <frame> \"<commands>\"");
            demo_schedule_.emplace_back(std::strtoull(a.argv(1).c_str(), nullptr, 10),
                                        a.value_from(2));
        },
        "run commands when the next demo reaches a frame (scripted swaps, screenshots)");
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
            dispatch_->dump_scene_next_frame(a.argv(1), [this](const std::string& m) { print(m); });
        },
        "write the next frame's geometry for the ray-traced obscurance reference (vo_reference)");
    c.add_command(
        "r_plugin",
        [this](const CommandArgs& a) {
            if (a.argc() < 2) {
                return print("renderer: " + plugins_->active_name() +
                             " (r_plugins lists the others)");
            }
            swap_plugin(a.argv(1));
        },
        "load a renderer plugin by name, replacing the current one");
    c.add_command(
        "r_plugins",
        [this](const CommandArgs&) {
            for (const auto& p : plugins_->available()) {
                print((p.name == plugins_->active_name() ? "* " : "  ") + p.name + "  " + p.path);
            }
        },
        "list renderer plugins");
    c.add_command(
        "showroom",
        [this](const CommandArgs&) {
            if (demo_->active()) end_demo();
            show_showroom(true);
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
    std::string why = dispatch_->load_plugin(name);
    if (!why.empty()) {
        std::string current = plugins_->active_name();
        print("r_plugin: " + why + (current.empty() ? "" : "; keeping " + current));
        return;
    }
    host_.cvars().set(*cvars_.r_plugin, name);
    print("renderer: " + plugins_->active_name());
    if (level_models_registered_) warm_up_renderer(demo_->level());
}

void Engine::start_demo(const std::string& name, DemoMode mode) {
    // Played or not, a demo the command line asked for is its job (and keeps the loop off).
    demo_is_job_ = command_line_job_;
    std::string why = demo_->start(name, mode);
    if (!why.empty()) {
        if (mode != DemoMode::TimeDemo) return print(why);
        return timedemo_failed(name, why);
    }
    show_showroom(false);
    demo_loop_.set_playing(false);  // a demo chosen by hand ends the attract loop
    // The rest of the command line ("+timedemo demo +quit") waits for the demo to end.
    after_demo_text_ = host_.commands().take_pending_text();
    frame_times_.clear();
    gpu_timers_.reset();
    trace_.clear();
}

void Engine::end_demo() {
    if (!demo_->active()) return;
    const bool timedemo = demo_->mode() == DemoMode::TimeDemo && !demo_->live();
    if (timedemo) finish_timedemo();
    demo_->stop();
    demo_loop_.set_playing(false);
    demo_schedule_.clear();
    if (!vfs_) show_showroom(true);
    if (!after_demo_text_.empty()) {
        host_.commands().insert_text(after_demo_text_);
        after_demo_text_.clear();
    }
    if (timedemo && benchmark_ && !benchmark_->complete() && !quit_) queue_benchmark();
}

void Engine::begin_game(std::unique_ptr<LiveGame> game, const std::string& map) {
    if (demo_->active()) end_demo();
    show_showroom(false);
    demo_->start_game(std::move(game), map);
}

void Engine::update_command_line_job() {
    if (!command_line_job_ || !host_.commands().buffer_empty() || !after_demo_text_.empty()) return;
    // The attract loop (quake.rc's startdemos) is not the command line's job.
    if (demo_->active() && !demo_->live() && !demo_loop_.playing()) return;
    command_line_job_ = false;
}

void Engine::pause_demo(const CommandArgs& args) {
    if (!demo_->active()) return print("pause: no demo is playing");
    bool on = !demo_->paused();
    if (args.argc() > 1) on = parse_number_prefix(args.argv(1)) != 0;
    demo_->set_paused(on);
    print(on ? "paused" : "unpaused");
}

void Engine::finish_timedemo() {
    const FrameSummary summary = frame_times_.summarize();
    const std::string failure = timedemo_failure(summary);
    if (!failure.empty()) return timedemo_failed(demo_->name(), failure);
    report_timedemo(summary);
    write_frame_times(summary);
    write_frame_trace();
    if (benchmark_) benchmark_run_done(summary);
}

std::string Engine::timedemo_failure(const FrameSummary& summary) const {
    if (!demo_->failure().empty()) return demo_->failure();
    if (summary.frames == 0) return "no frame was played";
    return {};
}

// Said in the console during play; the process's exit status too when the command line ran it.
void Engine::timedemo_failed(const std::string& name, const std::string& why) {
    print("timedemo " + name + " failed (no frame rate reported): " + why);
    if (demo_is_job_) exit_status_ = 1;
    if (benchmark_) benchmark_failed(why);
}

void Engine::write_frame_times(const FrameSummary& summary) {
    if (!options_.bench_frames) return;
    FrameTimesHeader header{demo_->name(), plugins_->active_name(), window_->drawable_width(),
                            window_->drawable_height()};
    std::span<const double> counted = frame_times_.stored_seconds().subspan(1);
    if (counted.size() < summary.frames) print("benchframes: more frames than were stored");
    std::string error = append_frame_times(*options_.bench_frames, header, counted);
    if (!error.empty()) print("benchframes: " + error);
}

// After report_timedemo, which reads back the GPU times of the run's last frames.
void Engine::write_frame_trace() {
    if (!options_.bench_trace) return;
    TraceHeader header{demo_->name(), plugins_->active_name(), window_->drawable_width(),
                       window_->drawable_height()};
    std::string error = trace_.append_to(*options_.bench_trace, header, &gpu_timers_);
    if (!error.empty()) print("benchtrace: " + error);
}

void Engine::report_timedemo(const FrameSummary& s) {
    print(quake_timedemo_line(s));
    print(format("frame time: median %.2f ms, 95th %.2f ms, 99th %.2f ms; 1%% low %.1f fps",
                 s.median_ms, s.p95_ms, s.p99_ms, s.low1_fps));
    gpu_timers_.finish();
    BenchRecord record;
    record.demo = demo_->name();
    record.plugin = plugins_->active_name();
    record.width = window_->drawable_width();
    record.height = window_->drawable_height();
    record.gl_renderer = window_->gl_info().renderer;
    record.gl_version = window_->gl_info().version;
    record.frames = s;
    record.gpu_passes = gpu_timers_.totals();
    record.gpu_timing = !record.gpu_passes.empty();
    record.gpu_frames = gpu_timers_.frames_timed();
    for (const auto& pass : record.gpu_passes) {
        char line[128];
        std::snprintf(line, sizeof line, "  gpu %-12s %8.3f ms/frame", pass.name.c_str(),
                      pass.ms_per_frame);
        print(line);
    }
    if (options_.bench_json) {
        std::string error = append_bench_record(*options_.bench_json, record);
        if (!error.empty()) print("benchjson: " + error);
    }
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
    std::string error =
        save_screenshot(path, 0, window_->drawable_width(), window_->drawable_height());
    print(error.empty() ? "wrote " + path : "screenshot: " + error);
}

}  // namespace nq

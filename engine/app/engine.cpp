#include "app/engine.h"

#include <epoxy/gl.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <thread>

#include "common/file_io.h"
#include "formats/bsp.h"
#include "host/config_writer.h"

namespace nq {

namespace {

constexpr const char* kDefaultPlugin = "classic";

std::string executable_dir() {
    std::error_code ec;
    auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    return ec ? std::string(".") : exe.parent_path().string();
}

}  // namespace

Engine::Engine(const CommandLine& command_line)
    : command_line_(command_line),
      options_(read_launch_options(command_line)),
      timedemo_({&host_, &options_, user_dir() + "/" + options_.game.value_or("id1"),
                 [this](std::string_view text) { print(text); }, [this] { quit_ = true; },
                 [this] { exit_status_ = 1; }}) {
    host_.set_print([this](std::string_view text) { print(text); });
}

Engine::~Engine() {
    overlay_.reset();   // the menu reads the session and the plugins
    sound_.reset();     // the device's callback stops before anything it reads goes
    sessions_.reset();  // a recording ends here
    frames_.reset();
    timedemo_.gpu_timers().shutdown();
}

void Engine::print(std::string_view text) {
    std::string line(text);
    if (line.empty() || line.back() != '\n') line += '\n';
    std::fwrite(line.data(), 1, line.size(), stdout);
    std::fflush(stdout);
    if (overlay_) overlay_->console().print(line);
}

std::string Engine::user_dir() const {
    if (auto dir = command_line_.value("-userdir")) return *dir;
    const char* home = std::getenv("HOME");
    return std::string(home && *home ? home : ".") + "/.nprquake";
}

bool Engine::start() {
    for (const auto& e : options_.errors) print("command line: " + e);
    cvars_.r_plugin =
        host_.cvars().register_cvar({"r_defaultplugin",
                                     kDefaultPlugin,
                                     kCvarArchive,
                                     "renderer plugin loaded at start-up (r_plugin sets it)",
                                     {},
                                     {}});
    cvars_.fov = host_.cvars().register_cvar(
        {"fov", "90", kCvarArchive, "horizontal field of view in degrees", 10.0f, 170.0f});
    cvars_.host_maxfps = host_.cvars().register_cvar(
        {"host_maxfps", "250", kCvarArchive, "frame rate cap outside timedemo (0 = uncapped)", 0.0f,
         10000.0f});
    cvars_.showroom_time = host_.cvars().register_cvar(
        {"showroom_time", "-1", 0,
         "showroom clock in seconds: -1 follows the wall clock, >= 0 holds the scene still", -1.0f,
         1.0e6f});
    cvars_.viewmodel_quake = host_.cvars().register_cvar(
        {"r_viewmodel_quake", "0", kCvarArchive,
         "1: raise the weapon with the status bar's size, as GLQuake did (0: as QuakeSpasm)", 0.0f,
         1.0f});
    cvars_.draw_viewmodel = host_.cvars().register_cvar(
        {"r_drawviewmodel", "1", kCvarArchive, "0: the player's weapon is not drawn", 0.0f, 1.0f});
    cvars_.occlusion = host_.cvars().register_cvar(
        {"r_occlusion", "1", kCvarArchive,
         "1: models the world hides completely are flagged so plugins skip them (0: off)", 0.0f,
         1.0f});
    cvars_.host_framerate = host_.cvars().register_cvar(
        {"host_framerate", "0", 0,
         "fixed seconds per frame for the game and demos (0 = real time); scripted, "
         "deterministic runs use 1/72 = 0.0138889",
         0.0f, 1.0f});
    cvars_.menu_scale = host_.cvars().register_cvar(
        {"scr_menuscale", "1", kCvarArchive,
         "menu scale on Quake's 320x200 menu canvas (limited to what fits the screen)", 1.0f,
         10.0f});
    obscurance_cvars_.register_cvars(host_.cvars(), [this](const std::string& t) { print(t); });
    sound_ = std::make_unique<GameSound>(host_, command_line_.has("-nosound"),
                                         [this](std::string_view t) { print(t); });
    sound_->set_reader([this](const std::string& path) -> Result<std::vector<uint8_t>> {
        if (!vfs_) return Error{path, 0, "no game data mounted"};
        return vfs_->read(path);
    });
    cvars_.gamma = host_.cvars().register_cvar(
        {"gamma", "1", kCvarArchive,
         "brightness: each colour becomes colour^gamma (below 1 brighter; 1 costs nothing)", 0.3f,
         3.0f});
    cvars_.contrast = host_.cvars().register_cvar(
        {"contrast", "1", kCvarArchive,
         "each colour is multiplied by this before gamma, saturating at white (QuakeSpasm's; 1 "
         "costs nothing)",
         1.0f, 2.0f});

    mount_game_data();
    auto screen = Screen::open(options_, [this](std::string_view text) { print(text); });
    if (!screen) {
        print(screen.error().message);
        exit_status_ = 1;
        return false;
    }
    screen_ = std::move(screen.value());
    overlay_ = std::make_unique<Overlay>(host_, game_data_, vfs_ ? &*vfs_ : nullptr,
                                         screen_->width(), screen_->height());
    for (const std::string& line : overlay_->take_start_messages()) print(line);
    timedemo_.gpu_timers().init(true);

    FrameRendererContext frame;
    frame.host = &host_;
    frame.vfs = vfs_ ? &*vfs_ : nullptr;
    frame.game_data = &game_data_;
    frame.gpu_timers = &timedemo_.gpu_timers();
    frame.trace = &timedemo_.trace();
    frame.plugin_dir = command_line_.value("-plugindir").value_or(executable_dir() + "/plugins");
    frame.print = [this](std::string_view text) { print(text); };
    frame.session_world = [this]() -> const Bsp* {
        return sessions_ && sessions_->session().active() ? sessions_->session().level().world_bsp()
                                                          : nullptr;
    };
    frames_ = std::make_unique<FrameRenderer>(std::move(frame));

    SessionContext sessions;
    sessions.host = &host_;
    sessions.vfs = vfs_ ? &*vfs_ : nullptr;
    sessions.options = &options_;
    sessions.timedemo = &timedemo_;
    sessions.user_game_dir = user_dir() + "/" + options_.game.value_or("id1");
    sessions.palette = game_data_.palette_bytes();
    sessions.print = [this](std::string_view t) { print(t); };
    sessions.center_print = [this](std::string_view t) { overlay_->console().center_print(t); };
    sessions.show_showroom = [this](bool on) { frames_->show_showroom(on); };
    sessions.describe_renderer = [this] { return describe_renderer(); };
    sessions.quitting = [this] { return quit_; };
    sessions.level_unloading = [this] { frames_->release_level_models(); };
    sessions.level_loaded = [this](Level& level) {
        frames_->register_level_models(level, frame_settings());
    };
    sessions.level_restarted = [this](Level& level) {
        frames_->level_restarted(level, frame_settings());
    };
    sessions_ = std::make_unique<SessionController>(std::move(sessions));

    overlay_->create_menu(frames_->plugins(), sessions_->session(),
                          user_dir() + "/" + options_.game.value_or("id1"));
    register_commands();
    timedemo_.register_commands(host_.commands());
    sessions_->register_commands();
    screen_->register_commands(host_, [this] {
        overlay_->console().set_screen_size(screen_->width(), screen_->height());
    });
    host_.set_file_reader([this](const std::string& path) -> std::optional<std::string> {
        std::string game = options_.game.value_or("id1");
        auto user = read_file(user_dir() + "/" + game + "/" + path);
        if (user) return std::string(user->begin(), user->end());
        if (!vfs_) return std::nullopt;
        auto bytes = vfs_->read(path);
        if (!bytes) return std::nullopt;
        return std::string(bytes->begin(), bytes->end());
    });
    host_.queue_startup(command_line_);
    timedemo_.queue_benchmark();
    host_.commands().execute();  // quake.rc (or config.cfg, autoexec.cfg), the +commands
    load_initial_plugin();
    if (!vfs_ && !sessions_->session().active()) frames_->show_showroom(true);
    // Quake's start without +commands: the menu, over the demo loop if there is one.
    if (vfs_ && command_line_.command_text().empty() && !options_.benchmark && !quit_) {
        overlay_->menu().open(MenuScreen::Main);
    }
    clock_.restart_frames();
    return true;
}

void Engine::mount_game_data() {
    std::string basedir = options_.basedir.value_or(".");
    auto config = VfsConfig::for_game(basedir, options_.game.value_or(""));
    auto vfs = Vfs::mount(config);
    if (!vfs) {
        print("no game data: " + vfs.error().message + " — showing the built-in showroom");
        return;
    }
    vfs_.emplace(std::move(vfs.value()));
    for (const auto& w : vfs_->warnings()) print("warning: " + w);
    game_data_ = load_game_data(&*vfs_);
    for (const auto& w : game_data_.warnings) print("warning: " + w);
}

void Engine::load_initial_plugin() {
    if (frames_->plugins().active()) return;
    for (const std::string& name :
         {cvars_.r_plugin->string(), std::string(kDefaultPlugin), std::string("null")}) {
        std::string why = frames_->load_plugin(name);
        if (why.empty()) {
            print("renderer: " + frames_->plugins().active_name());
            return;
        }
        print("r_plugin: " + why);
    }
}

int Engine::run() {
    while (!quit_) frame();
    write_config();
    return exit_status_;
}

void Engine::frame() {
    FrameTrace& trace = timedemo_.trace();
    trace.begin_frame();
    const double now = FrameClock::now();
    double frame_time = clock_.begin_frame(now);
    if (cvars_.host_framerate->value() > 0) frame_time = cvars_.host_framerate->value();
    handle_events();
    host_.commands().execute();
    overlay_->console().update(clock_.since_start(now));
    trace.lap(TraceStage::Input);
    const SessionFrame session =
        sessions_->run_frame(frame_time, overlay_->open(), overlay_->console().is_open());
    if (session.ran) trace.lap(TraceStage::Demo);
    render(frame_time);
    update_sound(frame_time);
    trace.lap(TraceStage::Sound);
    trace.end_frame(session.timedemo_frame);
    if (std::optional<double> startup = clock_.first_frame_done()) {
        print("start-up to first frame: " + std::to_string(*startup) + " s");
    }
    if (session.timedemo_frame) timedemo_.record_frame(FrameClock::now() - now);
    sessions_->frame_drawn(FrameClock::now() - now, session);
    if (!session.timedemo_frame && cvars_.host_maxfps->value() > 0) {
        double budget = 1.0 / cvars_.host_maxfps->value() - (FrameClock::now() - now);
        if (budget > 0) std::this_thread::sleep_for(std::chrono::duration<double>(budget));
    }
}

void Engine::handle_events() {
    InputEvent event;
    while (screen_->poll_event(event)) {
        if (event.type == InputEventType::Quit) quit_ = true;
        if (event.type == InputEventType::Resize) {
            overlay_->console().set_screen_size(screen_->width(), screen_->height());
        }
        if (overlay_->menu_takes_event(event, sessions_->session().active(), menu_screen())) {
            continue;
        }
        const bool playing = sessions_->session().live() && !overlay_->open();
        if (event.type == InputEventType::MouseMotion && playing) {
            sessions_->input().add_mouse(float(event.dx), float(event.dy));
        }
        if (event.type == InputEventType::FocusLost) sessions_->input().release_all();
        overlay_->console().handle_event(event);
    }
    screen_->set_text_input(overlay_->console().is_open());
    // The mouse turns the view while a game runs and nothing is open.
    screen_->set_relative_mouse(sessions_->session().live() && !overlay_->open());
}

FrameSettings Engine::frame_settings() {
    FrameSettings settings;
    settings.width = screen_->width();
    settings.height = screen_->height();
    settings.fov_x = cvars_.fov->value();
    settings.occlusion = cvars_.occlusion->value() != 0 && !screen_->multisampled();
    settings.view_model_lift = cvars_.viewmodel_quake->value() != 0
                                   ? view_model_lift_for(overlay_->hud().viewsize())
                                   : 0.0f;
    settings.draw_view_model = cvars_.draw_viewmodel->value() != 0;
    settings.showroom_time = cvars_.showroom_time->value();
    settings.obscurance = obscurance_cvars_.settings();
    return settings;
}

void Engine::render(double frame_time) {
    glViewport(0, 0, screen_->width(), screen_->height());
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    // GPU time of paused frames stays out of the timedemo report, like their CPU time.
    bool timed = !sessions_->session().paused();
    GpuPassTimers& gpu_timers = timedemo_.gpu_timers();
    FrameTrace& trace = timedemo_.trace();
    if (timed) {
        gpu_timers.begin_frame();
        trace.set_gpu_frame(gpu_timers.frame_serial());
    }
    trace.lap(TraceStage::FrameStart);
    double real_time = clock_.since_start(FrameClock::now());
    if (sessions_->session().active() && sessions_->session().level_ready()) {
        render_demo(real_time, static_cast<float>(frame_time));
    } else {
        frames_->draw_showroom(real_time, static_cast<float>(frame_time), frame_settings());
    }
    overlay_->draw(real_time, menu_screen());
    screen_->apply_levels({cvars_.gamma->value(), cvars_.contrast->value()});
    if (timed) gpu_timers.end_frame();
    trace.lap(TraceStage::Overlay);
    screen_->swap();
    trace.lap(TraceStage::Swap);
}

void Engine::render_demo(double real_time, float frame_time) {
    const ViewResult view =
        frames_->draw_level(sessions_->session().level(), sessions_->session().client(),
                            sessions_->session().paused(), real_time, frame_time, frame_settings());
    // Engine-drawn, whatever the plugin: the tints over the 3D view, then the status bar.
    overlay_->hud().draw(sessions_->session().client(), view.eye_contents, screen_->width(),
                         screen_->height(), real_time);
}

void Engine::write_config() {
    std::string dir = user_dir() + "/" + options_.game.value_or("id1");
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    std::string error = ::nq::save_config(dir + "/" + kConfigFile, host_.cvars(), host_.bindings());
    if (!error.empty()) print("config: " + error);
}

HudScreen Engine::menu_screen() const {
    return HudScreen{screen_->width(), screen_->height(), cvars_.menu_scale->value()};
}

int run_nprquake(int argc, char** argv) {
    Engine engine(CommandLine::from_main(argc, argv));
    if (!engine.start()) return 1;
    return engine.run();
}

}  // namespace nq

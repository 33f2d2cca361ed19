// nprquake: the engine that ties everything together. It owns the host core (cvars, commands),
// the virtual filesystem, the window, the console, the renderer plugins and what they draw
// (a demo's level, or the showroom), and runs the frame loop:
//
//   events -> command buffer -> demo (client state) -> scene (nqr_frame) -> plugin hooks
//   -> view tints and status bar (hud) -> console -> gamma -> swap (and wait while the driver
//   has too many frames queued)
//   -> timedemo statistics
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/benchmark_runs.h"
#include "app/demo_loop.h"
#include "app/demo_session.h"
#include "app/engine_menu.h"
#include "app/game/game_controller.h"
#include "app/game_data.h"
#include "app/host_services.h"
#include "app/obscurance_cvars.h"
#include "app/render_dispatch.h"
#include "app/scene_builder.h"
#include "app/showroom.h"
#include "client/player_input.h"
#include "client/view.h"
#include "console/console.h"
#include "console/console_drawer.h"
#include "fs/vfs.h"
#include "host/command_line.h"
#include "host/host_core.h"
#include "host/launch_options.h"
#include "hud/hud.h"
#include "menu/menu.h"
#include "plugin/plugin_host.h"
#include "sound/game_sound.h"
#include "video/frame_stats.h"
#include "video/frame_throttle.h"
#include "video/frame_trace.h"
#include "video/gamma_pass.h"
#include "video/gpu_pass_timers.h"
#include "video/video_window.h"

namespace nq {

struct EngineCvars {
    Cvar* r_plugin = nullptr;
    Cvar* fov = nullptr;
    Cvar* host_maxfps = nullptr;
    Cvar* showroom_time = nullptr;
    Cvar* viewmodel_quake = nullptr;
    Cvar* draw_viewmodel = nullptr;
    Cvar* occlusion = nullptr;
    Cvar* gamma = nullptr;
    Cvar* host_framerate = nullptr;
    Cvar* menu_scale = nullptr;
    Cvar* vid_width = nullptr;
    Cvar* vid_height = nullptr;
    Cvar* vid_fullscreen = nullptr;
};

class Engine {
  public:
    explicit Engine(const CommandLine& command_line);
    ~Engine();
    Engine(const Engine&) = delete;
    Engine& operator=(const Engine&) = delete;

    // Mounts data, opens the window, loads the renderer; false (after printing why) when the
    // engine cannot run at all.
    bool start();
    // Runs frames until `quit`; returns the process exit status.
    int run();

    // Console output: the console, and stdout so headless runs and logs see everything.
    void print(std::string_view text);

  private:
    // engine.cpp
    void mount_game_data();
    bool open_window();
    void create_hud();  // after the window: the HUD's pictures go to the GPU
    void load_initial_plugin();
    void frame();
    void render(double frame_time);
    void render_demo(double real_time, float frame_time);
    void render_showroom(double real_time, float frame_time);
    void run_demo_schedule();
    CameraSetup camera_for(const ViewResult& view) const;
    void handle_events();
    double seconds() const;
    void write_config();
    std::string user_dir() const;

    // engine_menu.cpp
    void create_menu();
    bool menu_takes_event(const InputEvent& event);
    HudScreen menu_screen() const;
    void draw_menu(double real_time);

    // video_commands.cpp
    void register_video_commands();
    bool video_mode_locked() const;
    void restart_video();

    // demo_loop_commands.cpp
    void register_demo_loop_commands();
    void start_demo_loop(const CommandArgs& args);
    void play_next_loop_demo();
    void continue_demo_loop(bool failed);
    // engine_sound.cpp
    void update_sound(double frame_time);

    // engine_models.cpp
    void register_level_models(Level& level);
    // Draws the level's warm-up frame (SceneBuilder::build_warm_up) and waits for it, so the
    // driver's first-use costs land at load; the next frame clears it before anything shows.
    void warm_up_renderer(Level& level);
    void level_restarted(Level& level);
    void release_level_models();
    void show_showroom(bool on);

    // engine_commands.cpp
    void register_commands();
    void start_demo(const std::string& name, DemoMode mode);
    void end_demo();
    // A game (GameController: map, load) replaces the demo or showroom on screen.
    void begin_game(std::unique_ptr<LiveGame> game, const std::string& map);
    void pause_demo(const CommandArgs& args);
    // A timedemo ended: its report, or (when it failed) why, and never a frame rate then.
    void finish_timedemo();
    std::string timedemo_failure(const FrameSummary& summary) const;
    void timedemo_failed(const std::string& name, const std::string& why);
    void report_timedemo(const FrameSummary& summary);
    void write_frame_times(const FrameSummary& summary);
    void write_frame_trace();

    // engine_benchmark.cpp: -benchmark DEMO -benchmarkruns N
    void queue_benchmark();
    void benchmark_run_done(const FrameSummary& summary);
    void benchmark_failed(const std::string& why);
    void log_benchmark(const std::string& failure);
    // The command line's commands are running (a timedemo they start is the process's job:
    // its failure is the exit status); false once they and the demos they started are done.
    void update_command_line_job();
    void screenshot(const std::string& name);
    void print_view_position();
    void swap_plugin(const std::string& name);

    CommandLine command_line_;
    LaunchOptions options_;
    HostCore host_;
    EngineCvars cvars_;
    ObscuranceCvars obscurance_cvars_;
    std::optional<Vfs> vfs_;
    GameData game_data_;
    std::optional<VideoWindow> window_;
    GpuPassTimers gpu_timers_;
    FrameTrace trace_;        // -benchtrace
    FrameThrottle throttle_;  // after window_: goes while the context is still there
    std::unique_ptr<Console> console_;
    std::optional<ConsoleDrawer> console_drawer_;
    std::unique_ptr<Hud> hud_;
    std::optional<GammaPass> gamma_pass_;
    std::unique_ptr<HostServices> services_;
    std::unique_ptr<PluginHost> plugins_;
    std::unique_ptr<RenderDispatch> dispatch_;
    std::unique_ptr<DemoSession> demo_;
    std::unique_ptr<PlayerInput> input_;
    std::unique_ptr<EngineMenuServices> menu_services_;
    std::unique_ptr<Menu> menu_;  // after hud_ and plugins_, whose pictures and styles it shows
    DemoLoop demo_loop_;
    std::unique_ptr<GameController> game_;  // after demo_ and input_, which it plays through
    SceneBuilder scene_;
    ViewState view_state_;
    std::unique_ptr<GameSound> sound_;
    Listener listener_;  // the view drawn last, where sound is heard from
    std::unique_ptr<Showroom> showroom_;
    bool showroom_models_registered_ = false;
    bool level_models_registered_ = false;

    // Timedemo: per-frame times, and the command text that waits for the demo to end.
    FrameTimeRecorder frame_times_;
    std::string after_demo_text_;
    std::optional<BenchmarkRuns> benchmark_;
    bool command_line_job_ = true;
    bool demo_is_job_ = false;  // the demo playing was started by the command line's commands
    std::vector<std::pair<uint64_t, std::string>> demo_schedule_;  // demo_at FRAME "commands"
    double start_seconds_ = 0;
    double last_frame_seconds_ = 0;
    double first_frame_seconds_ = -1;  // for the start-up-to-first-frame report
    double demo_real_time_ = 0;        // wall clock of the demo frame drawn last (for pause)
    uint64_t frame_count_ = 0;
    bool quit_ = false;
    bool relative_mouse_ = false;       // the mouse turns the view (a game runs, nothing open)
    bool multisampled_screen_ = false;  // occlusion culling is then off
    int exit_status_ = 0;
};

int run_nprquake(int argc, char** argv);

}  // namespace nq

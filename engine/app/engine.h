// nprquake's shell: it reads the command line, mounts the game data, registers its own cvars
// and commands (quit, r_plugin, screenshot, showroom, path) and runs the frame loop over its
// wings, each with its own state (docs/architecture.md):
//
//   events (screen, overlay) -> command buffer -> the session's frame (sessions: a demo or the
//   game) -> the frame drawn (frame: scene, plugin hooks) -> HUD, menu, console (overlay)
//   -> gamma and swap (screen) -> sound -> timedemo statistics (timedemo)
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "app/frame/frame_renderer.h"
#include "app/obscurance_cvars.h"
#include "app/sessions/session_controller.h"
#include "app/shell/frame_clock.h"
#include "app/shell/game_data.h"
#include "app/shell/overlay.h"
#include "app/shell/screen.h"
#include "app/timedemo/timedemo_controller.h"
#include "fs/vfs.h"
#include "host/command_line.h"
#include "host/host_core.h"
#include "host/launch_options.h"
#include "sound/game_sound.h"

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
    Cvar* contrast = nullptr;
    Cvar* host_framerate = nullptr;
    Cvar* menu_scale = nullptr;
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
    void load_initial_plugin();
    void frame();
    void render(double frame_time);
    void render_demo(double real_time, float frame_time);
    // This frame's settings for the frame wing, from cvars and the screen.
    FrameSettings frame_settings();
    void handle_events();
    void write_config();
    std::string user_dir() const;

    HudScreen menu_screen() const;  // the menu's canvas on this screen

    // engine_sound.cpp
    void update_sound(double frame_time);

    // engine_commands.cpp
    void register_commands();
    // The renderer and screen of a timedemo run, as the timedemo wing reports them.
    TimedemoRun describe_renderer() const;
    void screenshot(const std::string& name);
    void swap_plugin(const std::string& name);

    CommandLine command_line_;
    LaunchOptions options_;
    HostCore host_;
    EngineCvars cvars_;
    ObscuranceCvars obscurance_cvars_;
    std::optional<Vfs> vfs_;
    GameData game_data_;
    std::unique_ptr<Screen> screen_;         // the window: it goes last, with the GL context
    TimedemoController timedemo_;            // its GPU timers go while the context is still there
    std::unique_ptr<Overlay> overlay_;       // HUD, menu and console over every frame
    std::unique_ptr<FrameRenderer> frames_;  // plugins, their models, the frame drawn
    std::unique_ptr<SessionController> sessions_;  // the demo or game played, the demo loop
    std::unique_ptr<GameSound> sound_;

    FrameClock clock_;
    bool quit_ = false;
    int exit_status_ = 0;
};

int run_nprquake(int argc, char** argv);

}  // namespace nq

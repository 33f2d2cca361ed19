// The sessions wing of the engine: what is played — a demo (playdemo, timedemo), Quake's attract
// loop (startdemos, demos, stopdemo) or a game (the game wing, app/game) — in one DemoSession
// with the player's input, and the commands that start, stop, pause and query it (stop, pause,
// viewpos). It runs the session's part of the host frame and tells the timedemo wing when a
// demo starts and ends. The shell gives it the showroom switch and its view of the run (the
// renderer and the screen) through SessionContext.
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <string_view>

#include "app/game/game_controller.h"
#include "app/sessions/demo_loop.h"
#include "app/sessions/demo_session.h"
#include "app/timedemo/timedemo_controller.h"
#include "client/player_input.h"
#include "host/host_core.h"
#include "host/launch_options.h"

namespace nq {

class Vfs;

// What the wing needs of the engine; the pointers outlive the controller.
struct SessionContext {
    HostCore* host = nullptr;
    const Vfs* vfs = nullptr;  // null without game data: the showroom shows between sessions
    const LaunchOptions* options = nullptr;
    TimedemoController* timedemo = nullptr;
    std::string user_game_dir;           // <userdir>/<game>: saves, recorded demos
    std::array<uint8_t, 768> palette{};  // surface colours for the ambient cube field
    std::function<void(std::string_view)> print;
    std::function<void(std::string_view)> center_print;
    std::function<void(bool on)> show_showroom;
    // The renderer and screen of the run, for the timedemo's report (demo fields left empty).
    std::function<TimedemoRun()> describe_renderer;
    std::function<bool()> quitting;
    // The renderer's side of a level: its models arrive, stay (the same map again) or go.
    std::function<void(Level&)> level_loaded;
    std::function<void(Level&)> level_restarted;
    std::function<void()> level_unloading;
};

// What one frame of the session was.
struct SessionFrame {
    bool timedemo_frame = false;  // counted by the timedemo (a paused or ended one is not)
    bool game_frame = false;      // a frame of a running, unpaused game
    bool ran = false;             // a demo or game was running
};

class SessionController {
  public:
    explicit SessionController(SessionContext context);
    ~SessionController();
    SessionController(const SessionController&) = delete;
    SessionController& operator=(const SessionController&) = delete;

    void register_commands();

    DemoSession& session() { return *session_; }
    const DemoSession& session() const { return *session_; }
    PlayerInput& input() { return *input_; }
    GameController& game() { return *game_; }

    // The session's part of the host frame. A single-player game waits (`game_waits`) while
    // the menu or console is open; a demo that ends here ends, and the loop goes on.
    SessionFrame run_frame(double frame_time, bool game_waits, bool console_open);
    // After the frame was drawn: the game's frame statistics and the command line's job.
    void frame_drawn(double seconds, const SessionFrame& frame);

    void end_demo();

  private:
    void start_demo(const std::string& name, DemoMode mode);
    void begin_game(std::unique_ptr<LiveGame> game, const std::string& map);
    void pause(const CommandArgs& args);
    void print_view_position();
    TimedemoRun describe_run() const;
    // demo_loop_commands.cpp
    void register_demo_loop_commands();
    void start_demo_loop(const CommandArgs& args);
    void play_next_loop_demo();
    void continue_demo_loop(bool failed);

    SessionContext context_;
    std::unique_ptr<PlayerInput> input_;
    std::unique_ptr<DemoSession> session_;
    DemoLoop loop_;
    std::unique_ptr<GameController> game_;  // after session_ and input_, which it plays through
};

}  // namespace nq

// The game wing of the engine: the game's cvars (Quake's names and defaults), the commands that
// start, change, save, load and record a game, the cheats, and the host frame's part that turns
// the player's input into server frames. It owns the server's view of the engine
// (EngineServerHost) and the game's frame-time statistics; the engine shell gives it the
// session the game plays in and is asked, through GameContext::begin_game, to put a new game
// on screen (ending a demo, hiding the showroom).
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <string_view>

#include "app/game/engine_server_host.h"
#include "app/sessions/demo_session.h"
#include "client/player_input.h"
#include "host/host_core.h"
#include "server/server.h"
#include "video/frame_stats.h"

namespace nq {

class Vfs;

namespace server {
struct ServerLevel;
}

// What the game wing needs of the engine; every reference outlives the controller.
struct GameContext {
    HostCore* host = nullptr;
    DemoSession* session = nullptr;
    PlayerInput* input = nullptr;
    const Vfs* vfs = nullptr;   // null without game data
    std::string user_game_dir;  // <userdir>/<game>: saves and recorded demos go here
    std::function<void(std::string_view)> print;
    // A new game replaces whatever the session shows (the engine ends a demo, hides the
    // showroom, then starts `game` on `map` in the session).
    std::function<void(std::unique_ptr<LiveGame> game, const std::string& map)> begin_game;
};

// The game's cvars, read when a level starts (rules, seed, protocol) or each frame (physics).
struct GameCvars {
    Cvar* skill = nullptr;
    Cvar* deathmatch = nullptr;
    Cvar* coop = nullptr;
    Cvar* sv_protocol = nullptr;
    Cvar* sv_gravity = nullptr;
    Cvar* sv_maxspeed = nullptr;
    Cvar* sv_friction = nullptr;
    Cvar* sv_edgefriction = nullptr;
    Cvar* sv_stopspeed = nullptr;
    Cvar* sv_accelerate = nullptr;
    Cvar* sv_maxvelocity = nullptr;
    Cvar* sv_nostep = nullptr;
    Cvar* sv_seed = nullptr;
};

class GameController {
  public:
    // Registers the game's cvars and commands (map, changelevel, restart, record, save, load,
    // the cheats, status, serverprofile, gamestats).
    explicit GameController(GameContext context);

    // One host frame of the running game: the player's move (none while `input_blocked`: the
    // console is open) to the server, whose messages reach the client; then a changelevel
    // QuakeC asked for. `frame_time` 0 holds the game still (a menu is open).
    FrameStatus run_frame(double frame_time, bool input_blocked);
    // After the frame was drawn: the time from `map` to the level's first frame is reported
    // once, and the frame's time is counted for `gamestats` when `counted` (a game ran in it,
    // unpaused).
    void frame_drawn(double frame_seconds, bool counted);

    // Ends a recording: false when none was running.
    bool stop_recording();

  private:
    void register_cvars();
    void register_commands();
    void register_cheats();
    void register_save_commands();  // save_commands.cpp
    void start_map(const std::string& map, server::SpawnParms parms);
    void change_level_if_asked();
    void start_recording(const CommandArgs& args);
    server::ServerSettings server_settings() const;
    server::ServerLevel* level();
    void print(std::string_view text) const { context_.print(text); }

    GameContext context_;
    GameCvars cvars_;
    EngineServerHost server_host_;
    FrameTimeRecorder frame_times_{size_t{1} << 16};  // host frames of the running game
    double map_started_seconds_ = -1;                 // `map` ran: report its first frame
};

}  // namespace nq

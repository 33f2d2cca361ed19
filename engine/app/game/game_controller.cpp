// The game wing: its cvars, `map`, `changelevel`, `restart`, `record`, the cheats, and the host
// frame's part that turns the player's input into server frames.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>

#include "app/game/game_controller.h"
#include "fs/vfs.h"
#include "host/number_text.h"
#include "server/server_commands.h"
#include "server/server_level.h"

namespace nq {

namespace {

CvarSpec numeric(const char* name, const char* value, uint32_t flags, const char* description,
                 float min, float max) {
    CvarSpec spec;
    spec.name = name;
    spec.default_value = value;
    spec.flags = flags;
    spec.description = description;
    spec.min_value = min;
    spec.max_value = max;
    return spec;
}

double now_seconds() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

}  // namespace

GameController::GameController(GameContext context)
    : context_(std::move(context)), server_host_(*context_.host, context_.vfs, context_.print) {
    register_cvars();
    register_commands();
    register_cheats();
    register_save_commands();
}

void GameController::register_cvars() {
    CvarRegistry& c = context_.host->cvars();
    GameCvars& g = cvars_;
    g.skill = c.register_cvar(numeric(
        "skill", "1", 0, "0 easy, 1 normal, 2 hard, 3 nightmare: read when a level starts", 0, 3));
    g.deathmatch = c.register_cvar(
        numeric("deathmatch", "0", 0, "deathmatch rules when a level starts", 0, 10));
    g.coop =
        c.register_cvar(numeric("coop", "0", 0, "cooperative rules when a level starts", 0, 1));
    g.sv_protocol = c.register_cvar(numeric("sv_protocol", "666", kCvarArchive,
                                            "protocol of the server's messages and so of recorded "
                                            "demos: 15 (NetQuake), 666 (FitzQuake), 999 (RMQ)",
                                            15, 999));
    g.sv_gravity =
        c.register_cvar(numeric("sv_gravity", "800", 0, "gravity, units/s^2", -100000, 100000));
    g.sv_maxspeed = c.register_cvar(
        numeric("sv_maxspeed", "320", 0, "fastest a player runs, units/s", 0, 100000));
    g.sv_friction = c.register_cvar(numeric("sv_friction", "4", 0, "ground friction", 0, 1000));
    g.sv_edgefriction =
        c.register_cvar(numeric("edgefriction", "2", 0, "friction factor at ledges", 0, 1000));
    g.sv_stopspeed = c.register_cvar(numeric(
        "sv_stopspeed", "100", 0, "speed below which friction stops a player quickly", 0, 100000));
    g.sv_accelerate =
        c.register_cvar(numeric("sv_accelerate", "10", 0, "player acceleration", 0, 1000));
    g.sv_maxvelocity = c.register_cvar(
        numeric("sv_maxvelocity", "2000", 0, "velocity clamp per axis, units/s", 0, 100000));
    g.sv_nostep =
        c.register_cvar(numeric("sv_nostep", "0", 0, "1: monsters cannot climb steps", 0, 1));
    g.sv_seed = c.register_cvar(numeric("sv_seed", "1", 0,
                                        "seed of the server's random numbers when a level starts "
                                        "(same seed, same input: same demo)",
                                        0, 2147483647.0f));
    c.register_cvar(numeric("sv_aim", "1", kCvarArchive,
                            "autoaim cone (cosine; 1 = off, Quake used 0.93)", 0, 1));
    c.register_cvar(
        numeric("developer", "0", 0, "1: print QuakeC's dprint and server warnings", 0, 1));
    // Cvars the stock QuakeC reads with cvar() (teamplay rules, level timers, temp1).
    for (const char* name : {"teamplay", "fraglimit", "timelimit", "noexit", "samelevel", "temp1",
                             "saved1", "saved2", "saved3", "saved4", "savedgamecfg", "scratch1",
                             "scratch2", "scratch3", "scratch4", "registered", "pausable"}) {
        CvarSpec spec;
        spec.name = name;
        spec.default_value = std::string_view(name) == "pausable" ? "1" : "0";
        c.register_cvar(spec);
    }
}

server::ServerSettings GameController::server_settings() const {
    server::ServerSettings s;
    const GameCvars& g = cvars_;
    s.protocol = g.sv_protocol->integer();
    if (!protocol::is_supported(s.protocol)) s.protocol = protocol::kFitzQuake;
    s.skill = g.skill->integer();
    s.deathmatch = g.deathmatch->integer() != 0;
    s.coop = g.coop->integer() != 0;
    s.random_seed = uint32_t(g.sv_seed->integer());
    s.physics.gravity = g.sv_gravity->value();
    s.physics.max_speed = g.sv_maxspeed->value();
    s.physics.friction = g.sv_friction->value();
    s.physics.edge_friction = g.sv_edgefriction->value();
    s.physics.stop_speed = g.sv_stopspeed->value();
    s.physics.accelerate = g.sv_accelerate->value();
    s.physics.max_velocity = g.sv_maxvelocity->value();
    s.physics.no_step = g.sv_nostep->value() != 0;
    return s;
}

server::ServerLevel* GameController::level() {
    LiveGame* game = context_.session->live();
    return game && game->running() ? game->server().level() : nullptr;
}

void GameController::start_map(const std::string& map, server::SpawnParms parms) {
    if (!context_.vfs) return print("map: no game data mounted");
    // Checked first: a changelevel to a missing map must not end the game being played.
    if (!context_.vfs->exists("maps/" + map + ".bsp")) {
        return print("map: cannot find maps/" + map + ".bsp" +
                     (level() ? "; the game goes on" : ""));
    }
    LiveGame* running = context_.session->live();
    const bool changing = parms != server::SpawnParms::fresh && running && running->running();
    const auto started = std::chrono::steady_clock::now();
    if (changing) {
        // The same game goes on: the client receives the new level's signon like any message.
        if (std::string why = running->start(map, server_settings(), parms); !why.empty()) {
            print("map: " + why);
            return;
        }
    } else {
        auto game = std::make_unique<LiveGame>(server_host_);
        if (std::string why = game->start(map, server_settings()); !why.empty()) {
            print("map: " + why);
            return;
        }
        context_.begin_game(std::move(game), map);
        frame_times_.clear();
    }
    context_.input->release_all();
    map_started_seconds_ = std::chrono::duration<double>(started.time_since_epoch()).count();
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    print("map " + map + ": loaded in " + std::to_string(int(seconds * 1000)) + " ms");
}

// QuakeC asked for another level (a trigger_changelevel): go there, carrying the player's parms.
void GameController::change_level_if_asked() {
    LiveGame* game = context_.session->live();
    if (!game || !game->running()) return;
    std::optional<std::string> next = game->server().take_changelevel();
    if (!next) return;
    start_map(*next, server::SpawnParms::carried);
}

FrameStatus GameController::run_frame(double frame_time, bool input_blocked) {
    LiveGame& game = *context_.session->live();
    PlayerInput& input = *context_.input;
    if (server::ServerLevel* running = level()) running->game.settings = server_settings().physics;
    if (auto angles = game.take_set_angles()) input.view_angles() = *angles;
    MoveCommand cmd;
    if (!input_blocked) cmd = input.build_move(float(frame_time));
    cmd.view_angles = input.view_angles();
    const FrameStatus status = context_.session->frame(frame_time, &cmd);
    if (auto angles = game.take_set_angles()) input.view_angles() = *angles;
    change_level_if_asked();
    return status;
}

void GameController::frame_drawn(double frame_seconds, bool counted) {
    DemoSession& session = *context_.session;
    if (map_started_seconds_ >= 0 && session.level_ready()) {
        const double ms = (now_seconds() - map_started_seconds_) * 1000;
        print("map " + session.name() + ": first frame " + std::to_string(int(ms)) +
              " ms after the map command");
        map_started_seconds_ = -1;
    }
    if (counted) frame_times_.record(frame_seconds);
}

void GameController::start_recording(const CommandArgs& a) {
    if (a.argc() < 2 || a.argc() > 3) return print("usage: record <demoname> [map]");
    std::string name = a.argv(1);
    if (name.find("..") != std::string::npos) return print("record: relative paths not allowed");
    if (name.size() < 4 || name.substr(name.size() - 4) != ".dem") name += ".dem";
    if (a.argc() == 3) start_map(a.argv(2), server::SpawnParms::fresh);
    LiveGame* game = context_.session->live();
    if (!game || !game->running()) return print("record: no game is running (record <name> <map>)");
    const std::string& dir = context_.user_game_dir;
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    const std::string path = dir + "/" + name;
    if (std::string why = game->start_recording(path, context_.input->view_angles());
        !why.empty()) {
        return print("record: " + why);
    }
    print("recording to " + path);
}

bool GameController::stop_recording() {
    LiveGame* game = context_.session->live();
    if (!game || !game->recorder().recording()) return false;
    const std::string path = game->recorder().path();
    const uint64_t blocks = game->recorder().blocks();
    const uint64_t bytes = game->stop_recording(context_.input->view_angles());
    print("completed demo " + path + ": " + std::to_string(blocks + 1) + " blocks, " +
          std::to_string(bytes) + " bytes");
    return true;
}

void GameController::register_commands() {
    CommandSystem& c = context_.host->commands();
    c.add_command(
        "map",
        [this](const CommandArgs& a) {
            if (a.argc() < 2) return print("usage: map <name>");
            stop_recording();
            start_map(a.argv(1), server::SpawnParms::fresh);
        },
        "start a new game on a map (map start)");
    c.add_command(
        "changelevel",
        [this](const CommandArgs& a) {
            if (a.argc() < 2) return print("usage: changelevel <name>");
            if (!level()) return print("changelevel: no game is running (use map)");
            start_map(a.argv(1), server::SpawnParms::carried);
        },
        "go to another map keeping the player's health, items and ammo");
    c.add_command(
        "restart",
        [this](const CommandArgs&) {
            server::ServerLevel* running = level();
            if (!running) return print("restart: no game is running");
            const std::string map = running->map_name;  // the level goes when the map starts
            start_map(map, server::SpawnParms::restart);
        },
        "start the current map again");
    c.add_command(
        "record", [this](const CommandArgs& a) { start_recording(a); },
        "record the game to <userdir>/<game>/<name>.dem (record <name> [map])");
    c.add_command(
        "gamestats",
        [this](const CommandArgs&) {
            const FrameSummary s = frame_times_.summarize();
            print("game: " + quake_timedemo_line(s));
            char line[160];
            std::snprintf(
                line, sizeof line,
                "game frame time: median %.2f ms, 95th %.2f ms, 99th %.2f ms; 1%% low %.1f fps",
                s.median_ms, s.p95_ms, s.p99_ms, s.low1_fps);
            print(line);
            frame_times_.clear();
        },
        "host frame times while the game ran since the last gamestats (first frame excluded)");
    c.add_command(
        "serverprofile",
        [this](const CommandArgs& a) {
            LiveGame* game = context_.session->live();
            if (!game) return print("serverprofile: no game is running");
            if (a.argc() > 1 && a.argv(1) == "clear") return game->server().clear_frame_profile();
            std::vector<float> ms = game->server().frame_profile();
            if (ms.empty()) return print("serverprofile: no server frames yet");
            std::sort(ms.begin(), ms.end());
            auto at = [&](double q) {
                return ms[std::min(ms.size() - 1, size_t(q * double(ms.size())))];
            };
            char line[200];
            std::snprintf(
                line, sizeof line,
                "server frames: %zu, median %.3f ms, 95th %.3f ms, 99th %.3f ms, max %.3f ms",
                ms.size(), double(at(0.5)), double(at(0.95)), double(at(0.99)), double(ms.back()));
            print(line);
        },
        "server frame times of this level (physics, QuakeC, messages); 'serverprofile clear' "
        "restarts");
}

// Cheats and the player's own commands, on the running level.
void GameController::register_cheats() {
    CommandSystem& c = context_.host->commands();
    auto cheat = [this](std::string (*fn)(server::ServerLevel&)) {
        return [this, fn](const CommandArgs&) {
            server::ServerLevel* running = level();
            if (!running) return print("no game is running");
            print(fn(*running));
        };
    };
    // The client flashes the screen itself when the server stuffs "bf"; the command the text
    // then runs has nothing left to do.
    c.add_command(
        "bf", [](const CommandArgs&) {}, "bonus flash (applied by the client)");
    c.add_command("god", cheat(&server::toggle_god), "toggle invulnerability");
    c.add_command("notarget", cheat(&server::toggle_notarget), "toggle monsters ignoring you");
    c.add_command("noclip", cheat(&server::toggle_noclip), "toggle flying through walls");
    c.add_command("fly", cheat(&server::toggle_fly), "toggle flying");
    c.add_command("status", cheat(&server::status_text), "the running game: map, time, player");
    c.add_command(
        "setpos",
        [this](const CommandArgs& a) {
            server::ServerLevel* running = level();
            if (!running) return print("no game is running");
            if (a.argc() != 4) return print("usage: setpos <x> <y> <z>");
            const server::Vec3f origin{parse_number_prefix(a.argv(1)),
                                       parse_number_prefix(a.argv(2)),
                                       parse_number_prefix(a.argv(3))};
            print(server::set_position(*running, origin));
        },
        "move the player to a point (setpos x y z), standing still");
    c.add_command(
        "kill",
        [this](const CommandArgs&) {
            server::ServerLevel* running = level();
            if (!running) return print("kill: no game is running");
            if (std::string why = server::kill_player(*running); !why.empty()) print(why);
        },
        "suicide (respawn)");
    c.add_command(
        "give",
        [this](const CommandArgs& a) {
            server::ServerLevel* running = level();
            if (!running) return print("give: no game is running");
            const float amount = a.argc() > 2 ? std::strtof(a.argv(2).c_str(), nullptr) : 0;
            if (std::string why = server::give(*running, a.argc() > 1 ? a.argv(1) : "", amount);
                !why.empty()) {
                print(why);
            }
        },
        "give <s|n|r|c|h|a|2..8> [amount]: ammo, health, armour or a weapon");
}

}  // namespace nq

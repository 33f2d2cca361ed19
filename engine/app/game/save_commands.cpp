// `save` and `load`: saved games in id Quake's text format (Host_Savegame_f, Host_Loadgame_f),
// written to <userdir>/<game>/NAME.sav and read from there or from the game data, so saves move
// between this engine and QuakeSpasm.
#include <filesystem>

#include "app/game/game_controller.h"
#include "common/file_io.h"
#include "fs/vfs.h"
#include "server/savegame.h"
#include "server/server_level.h"

namespace nq {

namespace {

// "NAME" as a file name in the game directory: ".sav" added when missing, "" when the name
// climbs out of the directory (Quake refuses "..").
std::string save_file_name(const std::string& name) {
    if (name.empty() || name.find("..") != std::string::npos || name.front() == '/') return "";
    if (name.size() >= 4 && name.compare(name.size() - 4, 4, ".sav") == 0) return name;
    return name + ".sav";
}

// Why the running level cannot be saved now, as Quake words it; "" when it can.
std::string save_refusal(const server::ServerLevel& level, Intermission intermission) {
    if (intermission != Intermission::None) return "Can't save in intermission.";
    if (level.vm->field_float(1, level.layout.fields.health) <= 0) {
        return "Can't savegame with a dead player";
    }
    return "";
}

}  // namespace

void GameController::register_save_commands() {
    CommandSystem& c = context_.host->commands();
    c.add_command(
        "save",
        [this](const CommandArgs& a) {
            if (a.argc() != 2) return print("save <savename> : save a game");
            server::ServerLevel* running = level();
            if (!running) return print("Not playing a local game.");
            if (std::string why = save_refusal(*running, context_.session->client().intermission());
                !why.empty()) {
                return print(why);
            }
            const std::string name = save_file_name(a.argv(1));
            if (name.empty()) return print("Relative pathnames are not allowed.");
            const std::string& dir = context_.user_game_dir;
            std::error_code ec;
            std::filesystem::create_directories(dir, ec);
            const std::string path = dir + "/" + name;
            const int skill = context_.session->live()->server().settings().skill;
            const std::string text =
                server::write_savegame(*running, server::savegame_comment(*running), skill);
            const std::span<const uint8_t> bytes(reinterpret_cast<const uint8_t*>(text.data()),
                                                 text.size());
            if (std::string why = write_file(path, bytes); !why.empty()) {
                return print("save: " + why);
            }
            print("Saved game to " + path);
        },
        "save the game to <userdir>/<game>/<name>.sav (Quake's text format)");
    c.add_command(
        "load",
        [this](const CommandArgs& a) {
            if (a.argc() != 2) return print("load <savename> : load a game");
            const std::string name = save_file_name(a.argv(1));
            if (name.empty()) return print("Relative pathnames are not allowed.");
            if (!context_.vfs) return print("load: no game data mounted");
            Result<std::vector<uint8_t>> bytes = read_file(context_.user_game_dir + "/" + name);
            if (!bytes) bytes = context_.vfs->read(name);
            if (!bytes) return print("load: cannot find " + name);
            const std::string_view text(reinterpret_cast<const char*>(bytes->data()),
                                        bytes->size());
            const Result<server::LoadedGame> saved = server::read_savegame(text, name);
            if (!saved) return print("load: " + saved.error().to_string());
            // The running game goes on when the save cannot be started.
            auto game = std::make_unique<LiveGame>(server_host_);
            if (std::string why = game->load(*saved, server_settings()); !why.empty()) {
                return print("load: " + why);
            }
            stop_recording();
            context_.host->cvars().set("skill", std::to_string(saved->skill));
            context_.begin_game(std::move(game), saved->map);
            context_.input->release_all();
            print("Loaded game " + name + " (" + saved->map + ")");
        },
        "load a game saved with save (or by QuakeSpasm): load <name>");
}

}  // namespace nq

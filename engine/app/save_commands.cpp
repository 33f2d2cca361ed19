// `save` and `load`: saved games in id Quake's text format (Host_Savegame_f, Host_Loadgame_f),
// written to <userdir>/<game>/NAME.sav and read from there or from the game data, so saves move
// between this engine and QuakeSpasm.
#include <filesystem>

#include "app/engine.h"
#include "common/file_io.h"
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

void Engine::register_save_commands() {
    CommandSystem& c = host_.commands();
    c.add_command(
        "save",
        [this](const CommandArgs& a) {
            if (a.argc() != 2) return print("save <savename> : save a game");
            server::ServerLevel* level = game_level();
            if (!level) return print("Not playing a local game.");
            if (std::string why = save_refusal(*level, demo_->client().intermission());
                !why.empty()) {
                return print(why);
            }
            const std::string name = save_file_name(a.argv(1));
            if (name.empty()) return print("Relative pathnames are not allowed.");
            const std::string dir = user_dir() + "/" + options_.game.value_or("id1");
            std::error_code ec;
            std::filesystem::create_directories(dir, ec);
            const std::string path = dir + "/" + name;
            const int skill = demo_->live()->server().settings().skill;
            const std::string text =
                server::write_savegame(*level, server::savegame_comment(*level), skill);
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
            if (!vfs_) return print("load: no game data mounted");
            const std::string game_dir = user_dir() + "/" + options_.game.value_or("id1");
            Result<std::vector<uint8_t>> bytes = read_file(game_dir + "/" + name);
            if (!bytes) bytes = vfs_->read(name);
            if (!bytes) return print("load: cannot find " + name);
            const std::string_view text(reinterpret_cast<const char*>(bytes->data()),
                                        bytes->size());
            const Result<server::LoadedGame> saved = server::read_savegame(text, name);
            if (!saved) return print("load: " + saved.error().to_string());
            // The running game goes on when the save cannot be started.
            auto game = std::make_unique<LiveGame>(*server_host_);
            if (std::string why = game->load(*saved, server_settings()); !why.empty()) {
                return print("load: " + why);
            }
            stop_recording();
            if (demo_->active()) end_demo();
            host_.cvars().set("skill", std::to_string(saved->skill));
            show_showroom(false);
            demo_->start_game(std::move(game), saved->map);
            input_->release_all();
            print("Loaded game " + name + " (" + saved->map + ")");
        },
        "load a game saved with save (or by QuakeSpasm): load <name>");
}

}  // namespace nq

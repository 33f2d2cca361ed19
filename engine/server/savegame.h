// Saved games in id Quake's text format (version 5), the one QuakeSpasm reads and writes, so
// saves move between the two engines:
//
//   5                        version
//   start_________________kills:__0/__9    comment: 39 characters, no spaces
//   16 lines "%f"            the player's spawn parms
//   1                        skill
//   start                    map
//   12.345678                server time
//   64 lines                 light styles ("m" for an unset one)
//   { "name" "value" ... }   the saved globals (ED_WriteGlobals)
//   { ... } per edict        every edict 0..num_edicts-1 (ED_Write); a free edict is "{ }"
//
// write_savegame produces that text from a running level; read_savegame parses it into plain
// data without touching any level (every malformed piece is an Error naming the file and byte
// offset); apply_savegame restores the data onto a level whose map has just been spawned (what
// Quake's Host_Loadgame_f does after SV_SpawnServer). Server::load_game ties the last two together.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "common/result.h"
#include "server/server_level.h"

namespace nq::server {

inline constexpr int kSaveVersion = 5;
inline constexpr size_t kSaveCommentLength = 39;  // Quake's SAVEGAME_COMMENT_LENGTH
inline constexpr size_t kSaveMaxToken = 1023;     // QuakeSpasm's com_token holds no more

// One "key" "value" pair of a globals or edict block, as written (no escapes undone).
struct SavedPair {
    std::string key, value;
    size_t offset = 0;  // of the key in the file, for messages
};

struct SavedBlock {
    std::vector<SavedPair> pairs;  // none: a free edict
    size_t offset = 0;             // of the opening brace
};

struct LoadedGame {
    std::string file_name;
    std::string comment;
    std::array<float, kNumSpawnParms> spawn_parms{};
    int skill = 1;  // 0..3
    std::string map;
    size_t map_offset = 0;  // where the map name stands, for a map that cannot be loaded
    double time = 0;
    std::array<std::string, kMaxLightStyles> lightstyles;
    SavedBlock globals;
    std::vector<SavedBlock> edicts;  // edict 0 (the world) first, then the player
};

// Quake's comment for the menu: the level's title (its worldspawn message) cut to 22
// characters, then "kills:%3i/%3i" at column 22, padded to 39.
std::string savegame_comment(const ServerLevel& level);

// The whole save file. `comment` is cut or padded to 39 characters with spaces and control
// characters turned into '_' (the format reads it as one word).
std::string write_savegame(const ServerLevel& level, std::string_view comment, int skill);

// Parses a save file's text. Only version 5 is accepted.
Result<LoadedGame> read_savegame(std::string_view text, const std::string& file_name);

// Restores `game` onto `level`, which has just spawned `game.map`: light styles, the clock,
// the globals by name, every edict's fields by name (a block without pairs frees its edict),
// the links of every edict in use, and the player's spawn parms. Baselines and the client's
// signon are the server's business. "" on success, else why the level cannot be used.
std::string apply_savegame(ServerLevel& level, const LoadedGame& game);

}  // namespace nq::server

// Server::load_game: a saved game started the way Quake's Host_Loadgame_f starts one.
#include <chrono>

#include "server/client_frame.h"
#include "server/savegame.h"
#include "server/server.h"
#include "server/server_level.h"

namespace nq::server {

namespace {
constexpr uint32_t kPlayer = 1;
}  // namespace

// The map's entities spawn as for a new game, because the precache lists, the static entities
// and the ambient sounds come from the spawn functions, not from the save. The settle frames
// are skipped: everything they would move is replaced by the save. Baselines are made from the
// restored edicts.
SpawnResult Server::load_game(const LoadedGame& game, const ServerSettings& settings) {
    const auto start = std::chrono::steady_clock::now();
    SpawnResult result;
    shutdown();
    error_.clear();
    settings_ = settings;
    settings_.skill = game.skill;
    result.error = load_level(game.map, settings_);
    if (!result.error.empty()) {
        result.error = Error{game.file_name, game.map_offset, result.error}.to_string();
    } else {
        level_->loading = false;
        result.error = apply_savegame(*level_, game);
    }
    if (!result.error.empty()) {
        error_ = result.error;
        shutdown();
        return result;
    }
    ServerLevel& level = *level_;
    level.datagram.clear();  // what the spawn functions sent is stale now
    level.reliable_datagram.clear();
    level.pending_changelevel.reset();
    write_baselines(level);
    join_saved_client();
    result.spawned = spawn_counts_.first;
    result.inhibited = spawn_counts_.second;
    result.load_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

// SV_Spawn_f with sv.loadgame set: the same signon as for a new player, but the saved edict
// is the player as it stands.
void Server::join_saved_client() {
    ServerLevel& level = *level_;
    ClientSlot& client = level.client;
    client.active = true;
    client.message.clear();
    write_prespawn(client.message);
    write_spawn_state(client.message);
    client.spawned = true;
    client.last_frags = int(level.vm->field_float(kPlayer, level.layout.fields.frags));
    for (std::vector<uint8_t>& b : blocks_) b.clear();
    blocks_[0].swap(client.message);
    used_blocks_ = 1;
}

}  // namespace nq::server

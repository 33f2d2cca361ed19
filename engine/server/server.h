// The local game server: loads progs.dat and a map, spawns the map's entities, runs the game
// frame by frame for the one local player, and writes what that player's client receives in
// Quake's wire protocol (666 by default, 15 or 999 selectable). The engine feeds those bytes into
// the same decoder and client state demos use; recording a demo is writing them to a file.
//
// The local client's signon happens inside spawn(): its first frame's messages carry the server
// info, the signon buffer (static entities and sounds, baselines), the spawn state and the
// client's stats, in the order a NetQuake client receives them.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "formats/protocol.h"
#include "server/game_state.h"
#include "server/server_host.h"

namespace nq::server {

struct ServerLevel;
struct LoadedGame;

struct ServerSettings {
    int protocol = protocol::kFitzQuake;
    int skill = 1;
    bool deathmatch = false;
    bool coop = false;
    uint32_t max_edicts = 8192;
    uint32_t random_seed = 1;
    PhysicsSettings physics;
};

// Where the player's spawn parms (health, items, ammo) come from when a level starts.
enum class SpawnParms {
    fresh,    // a new game: the progs' SetNewParms
    carried,  // changelevel: the player as the progs' SetChangeParms leaves them
    restart,  // the same level again: the parms the player entered it with
};

struct SpawnResult {
    std::string error;  // empty on success
    int spawned = 0, inhibited = 0;
    double load_seconds = 0;
};

class Server {
  public:
    explicit Server(ServerHost& host);
    ~Server();
    Server(const Server&) = delete;
    Server& operator=(const Server&) = delete;

    // Starts `map` (maps/<map>.bsp) with the player's parms from `parms`; carried and restart
    // parms need a level running before (without one, they are fresh).
    SpawnResult spawn(std::string_view map, const ServerSettings& settings,
                      SpawnParms parms = SpawnParms::fresh);
    void shutdown();
    bool active() const { return level_ != nullptr; }

    // Starts a saved game (server_load.cpp), as Quake's Host_Loadgame_f: the saved map spawns
    // with the saved skill, then the save replaces its edicts, globals, light styles and clock,
    // and the player joins as saved (no ClientConnect, no PutClientInServer).
    SpawnResult load_game(const LoadedGame& game, const ServerSettings& settings);

    // One server frame of `frame_time` seconds with the player's command. False when QuakeC
    // failed: error() says why, and the level has been shut down.
    bool frame(double frame_time, const UserCmd& cmd);
    // The messages the client receives from the last spawn() or frame(), in order.
    std::span<const std::vector<uint8_t>> client_messages() const {
        return {blocks_.data(), used_blocks_};
    }
    const std::string& error() const { return error_; }
    // A changelevel QuakeC asked for during the last frame, if any.
    std::optional<std::string> take_changelevel();

    // What a client joining now receives before the first frame (for `record` in mid-level):
    // server info, signon buffer, spawn state. Empty when no level runs.
    std::vector<uint8_t> signon_state() const;

    // Wall-clock milliseconds of the last server frames (physics, QuakeC and messages), up to
    // kProfileFrames of them, oldest first; kept in place, so profiling allocates nothing.
    static constexpr size_t kProfileFrames = 16384;
    std::vector<float> frame_profile() const;
    void clear_frame_profile() { profile_count_ = 0; }

    double time() const;
    const std::string& map_name() const;
    const ServerSettings& settings() const { return settings_; }  // of the running level
    ServerLevel* level() { return level_.get(); }

  private:
    std::string load_level(std::string_view map, const ServerSettings& settings);
    void connect_client(bool carried_parms);
    void save_spawn_parms();
    void join_saved_client();  // server_load.cpp
    void write_prespawn(std::vector<uint8_t>& out) const;
    void write_spawn_state(std::vector<uint8_t>& out) const;
    void send_frame();
    bool fail_level();

    ServerHost& host_;
    std::unique_ptr<ServerLevel> level_;
    std::vector<std::vector<uint8_t>> blocks_;
    size_t used_blocks_ = 0;
    std::string error_;
    std::array<float, 16> carried_parms_{};
    bool have_carried_parms_ = false;
    float serverflags_ = 0;  // carried across levels, as Quake's svs.serverflags
    ServerSettings settings_;
    std::array<float, kProfileFrames> profile_{};
    size_t profile_count_ = 0;
    std::pair<int, int> spawn_counts_{};  // spawned, inhibited
};

}  // namespace nq::server

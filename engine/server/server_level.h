// Everything one running level holds (Quake's `sv` and the one local client): the VM and its
// layout, the collision world, the precache lists, the messages being written, the clock. The
// server owns one per map; the builtins, the signon writer and the frame writer work on it.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "formats/bsp.h"
#include "formats/protocol.h"
#include "server/edict_pool.h"
#include "server/game_state.h"
#include "server/physics.h"
#include "server/progs_layout.h"
#include "server/random.h"
#include "server/server_host.h"
#include "server/world.h"
#include "vm/vm.h"

namespace nq::server {

inline constexpr int kMaxLightStyles = 64;
inline constexpr int kNumSpawnParms = 16;

// A client's stats slots (Quake's STAT_*), sent with svc_updatestat.
enum Stat {
    kStatTotalSecrets = 11,
    kStatTotalMonsters = 12,
    kStatSecrets = 13,
    kStatMonsters = 14
};

// What the client was last sent of an entity: baselines for the delta encoding.
struct Baseline {
    vm::Vec3f origin{}, angles{};
    int model = 0, frame = 0, colormap = 0, skin = 0, alpha = 0;
};

struct ClientSlot {
    bool active = false;   // connected
    bool spawned = false;  // PutClientInServer ran
    std::string name = "player";
    int colors = 0;
    std::array<float, kNumSpawnParms> spawn_parms{};
    UserCmd cmd;
    std::vector<uint8_t> message;  // reliable messages for this client
    int last_frags = 0;
};

struct ServerLevel {
    ServerLevel(ServerHost& host, std::unique_ptr<vm::Vm> vm, ProgsLayout layout);

    ServerHost& host;
    std::unique_ptr<vm::Vm> vm;
    ProgsLayout layout;
    World world;
    EdictPool edicts;
    GameState game;
    GameRandom random;

    std::string map_name;  // "start"
    std::shared_ptr<const Bsp> bsp;
    std::vector<std::string> model_names;                // precache list; [0] "", [1] the map
    std::vector<std::shared_ptr<const Bsp>> model_bsps;  // loaded .bsp item boxes
    std::vector<CollisionModel> collision;               // per model index
    std::vector<std::string> sound_names;                // precache list; [0] ""
    std::array<std::string, kMaxLightStyles> lightstyles;
    std::vector<Baseline> baselines;  // per edict

    protocol::ProtocolState protocol;
    bool loading = true;  // precaching is allowed while the entities spawn
    std::optional<std::string> pending_changelevel;
    std::vector<uint8_t> signon;             // sent once, at prespawn
    std::vector<uint8_t> datagram;           // unreliable, this frame, to every client
    std::vector<uint8_t> reliable_datagram;  // reliable, this frame, to every client
    ClientSlot client;                       // edict 1: the local player
    std::unique_ptr<SoundSink> sounds;       // what the physics' sounds are written through
    PhysicsContext physics;

    uint32_t max_clients() const { return edicts.max_clients(); }
    bool is_client(uint32_t edict) const { return edict >= 1 && edict <= max_clients(); }
    int model_index(std::string_view name) const;  // -1 when not precached
    int sound_index(std::string_view name) const;  // -1 when not precached
    // model_index of the QuakeC string `string` (a string value), remembered for the last
    // string asked: the player's weaponmodel is looked up every frame and rarely changes.
    int model_index_of_string(int32_t string);
    // The PVS row of the leaf holding `point` (empty: everything visible, as from inside solid). Rows are decompressed
    // on first use and kept, so a running level allocates nothing for them.
    std::span<const uint8_t> pvs_of(const vm::Vec3f& point);

  private:
    int32_t last_model_string_ = 0;
    int last_model_index_ = -1;  // only found indices are kept: a precache may come later
    std::vector<std::vector<uint8_t>> pvs_rows_;
    std::vector<uint8_t> pvs_ready_;
};

// Collision geometry for a precached model: "*N" is the map's submodel N, a ".bsp" file is
// loaded through the host, anything else (alias models, sprites) has none. A missing or broken
// file is a console warning and no geometry.
CollisionModel load_collision_model(ServerLevel& level, std::string_view name);

}  // namespace nq::server

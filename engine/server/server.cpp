#include "server/server.h"

#include <algorithm>
#include <chrono>

#include "formats/entities.h"
#include "server/builtins.h"
#include "server/client_frame.h"
#include "server/entity_spawner.h"
#include "server/message_writer.h"
#include "server/physics.h"
#include "server/player_move.h"
#include "server/server_level.h"
#include "server/server_messages.h"
#include "vm/progs.h"

namespace nq::server {

namespace {

using namespace protocol;

constexpr uint32_t kPlayer = 1;
constexpr int kSignonServerInfo = 1, kSignonPrespawn = 2, kSignonSpawn = 3;
constexpr double kSettleFrameTime = 0.1;  // Quake runs two frames of 0.1 s before anyone joins

void write_signon_num(std::vector<uint8_t>& out, const ProtocolState& p, int stage) {
    MessageWriter w(out, p);
    w.byte(svc_signonnum);
    w.byte(stage);
}

void write_server_info(const ServerLevel& level, const ServerSettings& settings,
                       std::vector<uint8_t>& out) {
    const vm::Vm& vm = *level.vm;
    MessageWriter w(out, level.protocol);
    w.byte(svc_print);
    w.string("\x02\nNPRQuake server, progs CRC " + std::to_string(vm.progs().crc) + "\n");
    w.byte(svc_serverinfo);
    w.lng(level.protocol.protocol);
    if (level.protocol.protocol == kRmq) w.lng(int32_t(level.protocol.flags));
    w.byte(int(level.max_clients()));
    w.byte(settings.deathmatch ? 1 : 0);
    w.string(vm.string_or_empty(vm.field_int(0, level.layout.fields.message)));
    for (size_t i = 1; i < level.model_names.size(); ++i) w.string(level.model_names[i]);
    w.byte(0);
    for (size_t i = 1; i < level.sound_names.size(); ++i) w.string(level.sound_names[i]);
    w.byte(0);
    const int track = int(vm.field_float(0, level.layout.fields.sounds));
    w.byte(svc_cdtrack);
    w.byte(track & 0xff);
    w.byte(track & 0xff);
    w.byte(svc_setview);
    w.shrt(int(kPlayer));
    write_signon_num(out, level.protocol, kSignonServerInfo);
}

void set_time_globals(ServerLevel& level) {
    level.vm->set_global_float(level.layout.globals.time, float(level.game.time));
    level.vm->set_global_float(level.layout.globals.frametime, level.game.frame_time);
}

}  // namespace

Server::Server(ServerHost& host) : host_(host) {
    blocks_.resize(2);
}
Server::~Server() = default;

double Server::time() const {
    return level_ ? level_->game.time : 0.0;
}

const std::string& Server::map_name() const {
    static const std::string kNone;
    return level_ ? level_->map_name : kNone;
}

std::optional<std::string> Server::take_changelevel() {
    if (!level_) return std::nullopt;
    std::optional<std::string> next = std::move(level_->pending_changelevel);
    level_->pending_changelevel.reset();
    return next;
}

void Server::shutdown() {
    level_.reset();
    used_blocks_ = 0;
}

bool Server::fail_level() {
    error_ = level_ && level_->vm->error() ? level_->vm->error()->to_string() : "server error";
    host_.print("SERVER ERROR: " + error_ + "\n");
    shutdown();
    return false;
}

std::string Server::load_level(std::string_view map, const ServerSettings& settings) {
    auto progs_bytes = host_.read_file("progs.dat");
    if (!progs_bytes) return "cannot find progs.dat";
    auto progs = vm::parse_progs(*progs_bytes, "progs.dat");
    if (!progs) return progs.error().to_string();
    auto layout = resolve_layout(*progs);
    if (!layout) return layout.error().to_string();
    const std::string path = "maps/" + std::string(map) + ".bsp";
    auto map_bytes = host_.read_file(path);
    if (!map_bytes) return "cannot find " + path;
    auto bsp = parse_bsp(*map_bytes, path);
    if (!bsp) return bsp.error().to_string();
    auto entities = parse_entities(bsp->entities, path, bsp->entities_offset);
    if (!entities) return entities.error().to_string();

    vm::VmLimits limits;
    limits.max_edicts = settings.max_edicts;
    auto machine = std::make_unique<vm::Vm>(std::move(*progs), limits);
    level_ = std::make_unique<ServerLevel>(host_, std::move(machine), *layout);
    ServerLevel& level = *level_;
    vm::Vm& vm = *level.vm;
    vm.set_builtins(game_builtins(), &level);
    level.map_name = std::string(map);
    level.bsp = std::make_shared<const Bsp>(std::move(*bsp));
    level.protocol.protocol = settings.protocol;
    level.random.seed(settings.random_seed);
    level.game.settings = settings.physics;
    level.sounds = std::make_unique<LevelSoundSink>(level);  // water splashes from the physics
    level.game.sounds = level.sounds.get();
    level.physics.host = &host_;

    level.model_names = {"", path};
    level.collision = {{}, {level.bsp.get(), 0}};
    for (size_t m = 1; m < level.bsp->models.size(); ++m) {
        level.model_names.push_back("*" + std::to_string(m));
        level.collision.push_back({level.bsp.get(), m});
    }
    level.sound_names = {""};
    level.edicts.reset(vm, 1);
    level.world.set_level(level.bsp.get(), level.collision);
    level.world.set_edict_pool(&level.edicts);
    level.game.time = 1.0;  // Quake starts a level at one second

    const GlobalOffsets& g = level.layout.globals;
    const FieldOffsets& f = level.layout.fields;
    vm.set_global_float(g.serverflags, serverflags_);
    vm.set_global_float(g.deathmatch, settings.deathmatch ? 1 : 0);
    vm.set_global_float(g.coop, settings.coop ? 1 : 0);
    vm.set_global_word(g.mapname, uint32_t(vm.strings().make_level(level.map_name)));
    vm.set_field_int(0, f.model, vm.strings().make_level(path));
    vm.set_field_float(0, f.modelindex, 1);
    vm.set_field_float(0, f.solid, qc::kSolidBsp);
    vm.set_field_float(0, f.movetype, qc::kMovePush);
    set_time_globals(level);

    vm.set_world_writable(true);
    SpawnReport report;
    const bool spawned =
        spawn_entities(level.game, *entities, {settings.skill, settings.deathmatch}, report);
    vm.set_world_writable(false);
    for (const std::string& warning : report.warnings) host_.debug_print(warning + "\n");
    if (!spawned) return vm.error()->to_string();
    spawn_counts_ = {report.spawned, report.inhibited};
    return "";
}

SpawnResult Server::spawn(std::string_view map, const ServerSettings& settings, SpawnParms parms) {
    const auto start = std::chrono::steady_clock::now();
    SpawnResult result;
    // Parms carry from the level being left (SetChangeParms ran when it asked to change).
    have_carried_parms_ = false;
    if (level_ && parms == SpawnParms::carried) save_spawn_parms();
    if (level_ && parms == SpawnParms::restart) {
        carried_parms_ = level_->client.spawn_parms;
        have_carried_parms_ = true;
    }
    shutdown();
    error_.clear();
    settings_ = settings;
    result.error = load_level(map, settings);
    if (!result.error.empty()) {
        error_ = result.error;
        shutdown();
        return result;
    }
    ServerLevel& level = *level_;
    // Let doors and plats settle, as Quake does before anyone joins.
    for (int i = 0; i < 2; ++i) {
        level.game.frame_time = float(kSettleFrameTime);
        if (!run_physics(level.game, {}, level.physics)) {
            result.error = level.vm->error()->to_string();
            fail_level();
            return result;
        }
        level.game.time += kSettleFrameTime;
    }
    level.loading = false;
    write_baselines(level);
    connect_client(have_carried_parms_);
    if (!level_) {
        result.error = error_;
        return result;
    }
    result.spawned = spawn_counts_.first;
    result.inhibited = spawn_counts_.second;
    result.load_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

// SV_SaveSpawnparms: the player's parms for the next level, as the progs' SetChangeParms makes
// them (keys and powerups dropped, health clamped), and the episode flags.
void Server::save_spawn_parms() {
    ServerLevel& level = *level_;
    vm::Vm& vm = *level.vm;
    const GlobalOffsets& g = level.layout.globals;
    serverflags_ = vm.global_float(g.serverflags);
    carried_parms_ = level.client.spawn_parms;
    have_carried_parms_ = true;
    if (!level.client.spawned) return;
    vm.set_global_word(g.self, vm.entity_value(kPlayer));
    if (!vm.execute(int32_t(vm.global_word(g.SetChangeParms)))) {
        host_.print("SetChangeParms: " + vm.error()->to_string() + "\n");
        return;
    }
    for (int i = 0; i < kNumSpawnParms; ++i) {
        carried_parms_[size_t(i)] = vm.global_float(g.parm1 + uint32_t(i));
    }
}

// SV_ConnectClient, prespawn, spawn and begin of the one local client, in one go. What QuakeC
// prints while the player joins lands between the signon and the spawn state, as in Quake.
void Server::connect_client(bool carried) {
    ServerLevel& level = *level_;
    vm::Vm& vm = *level.vm;
    const GlobalOffsets& g = level.layout.globals;
    const FieldOffsets& f = level.layout.fields;
    ClientSlot& client = level.client;
    client.active = true;
    if (carried) {
        client.spawn_parms = carried_parms_;
    } else {
        if (!vm.execute(int32_t(vm.global_word(g.SetNewParms)))) return void(fail_level());
        for (int i = 0; i < kNumSpawnParms; ++i) {
            client.spawn_parms[size_t(i)] = vm.global_float(g.parm1 + uint32_t(i));
        }
    }
    client.message.clear();
    write_prespawn(client.message);

    vm.clear_edict(kPlayer);
    vm.set_field_float(kPlayer, f.colormap, float(kPlayer));
    vm.set_field_float(kPlayer, f.team, float((client.colors & 15) + 1));
    vm.set_field_int(kPlayer, f.netname, vm.strings().make_level(client.name));
    for (int i = 0; i < kNumSpawnParms; ++i) {
        vm.set_global_float(g.parm1 + uint32_t(i), client.spawn_parms[size_t(i)]);
    }
    set_time_globals(level);
    vm.set_global_word(g.self, vm.entity_value(kPlayer));
    if (!vm.execute(int32_t(vm.global_word(g.ClientConnect)))) return void(fail_level());
    vm.set_global_word(g.self, vm.entity_value(kPlayer));
    if (!vm.execute(int32_t(vm.global_word(g.PutClientInServer)))) return void(fail_level());
    level.world.link(kPlayer, false);

    write_spawn_state(client.message);
    client.spawned = true;
    client.last_frags = int(vm.field_float(kPlayer, f.frags));
    for (std::vector<uint8_t>& b : blocks_) b.clear();
    blocks_[0].swap(client.message);
    used_blocks_ = 1;
}

// Server info, cd track, view entity, then the signon buffer (static entities and sounds,
// baselines): signon stages 1 and 2.
void Server::write_prespawn(std::vector<uint8_t>& out) const {
    ServerLevel& level = *level_;
    write_server_info(level, settings_, out);
    out.insert(out.end(), level.signon.begin(), level.signon.end());
    write_signon_num(out, level.protocol, kSignonPrespawn);
}

// The spawned player's state: time, light styles, scoreboard, level totals, view angles and
// client data, then signon stage 3.
void Server::write_spawn_state(std::vector<uint8_t>& out) const {
    ServerLevel& level = *level_;
    vm::Vm& vm = *level.vm;
    const GlobalOffsets& g = level.layout.globals;
    const FieldOffsets& f = level.layout.fields;
    MessageWriter w(out, level.protocol);
    w.byte(svc_time);
    w.flt(float(level.game.time));
    for (int i = 0; i < kMaxLightStyles; ++i) {
        w.byte(svc_lightstyle);
        w.byte(i);
        w.string(level.lightstyles[size_t(i)]);
    }
    w.byte(svc_updatename);
    w.byte(0);
    w.string(level.client.name);
    w.byte(svc_updatefrags);
    w.byte(0);
    w.shrt(int(vm.field_float(kPlayer, f.frags)));
    w.byte(svc_updatecolors);
    w.byte(0);
    w.byte(level.client.colors);
    const std::pair<int, uint32_t> stats[] = {{kStatTotalSecrets, g.total_secrets},
                                              {kStatTotalMonsters, g.total_monsters},
                                              {kStatSecrets, g.found_secrets},
                                              {kStatMonsters, g.killed_monsters}};
    for (const auto& [stat, global] : stats) {
        w.byte(svc_updatestat);
        w.byte(stat);
        w.lng(int32_t(vm.global_float(global)));
    }
    w.byte(svc_setangle);
    vm::Vec3f angles = vm.field_vector(kPlayer, f.angles);
    angles[2] = 0;
    w.angles(angles);
    write_client_data(level, kPlayer, out, false);
    write_signon_num(out, level.protocol, kSignonSpawn);
}

std::vector<uint8_t> Server::signon_state() const {
    std::vector<uint8_t> out;
    if (!level_) return out;
    write_prespawn(out);
    write_spawn_state(out);
    return out;
}

std::vector<float> Server::frame_profile() const {
    const size_t n = std::min(profile_count_, kProfileFrames);
    std::vector<float> out(n);
    const size_t first = profile_count_ - n;
    for (size_t i = 0; i < n; ++i) out[i] = profile_[(first + i) % kProfileFrames];
    return out;
}

bool Server::frame(double frame_time, const UserCmd& cmd) {
    if (!level_) return false;
    const auto started = std::chrono::steady_clock::now();
    ServerLevel& level = *level_;
    level.datagram.clear();
    level.game.frame_time = float(frame_time);
    set_time_globals(level);
    if (level.client.spawned) {
        level.client.cmd = cmd;
        apply_user_cmd(level.game, kPlayer, cmd);
        client_think(level.game, kPlayer, cmd);
    }
    const uint8_t spawned = level.client.spawned ? 1 : 0;
    if (!run_physics(level.game, std::span<const uint8_t>(&spawned, 1), level.physics)) {
        return fail_level();
    }
    level.game.time += frame_time;
    send_frame();
    const std::chrono::duration<float, std::milli> took =
        std::chrono::steady_clock::now() - started;
    profile_[profile_count_++ % kProfileFrames] = took.count();
    return true;
}

// SV_SendClientMessages for the local client: the datagram (time, client data, entities, the
// frame's sounds and particles), then the reliable stream.
void Server::send_frame() {
    ServerLevel& level = *level_;
    vm::Vm& vm = *level.vm;
    const FieldOffsets& f = level.layout.fields;
    ClientSlot& client = level.client;

    const int frags = int(vm.field_float(kPlayer, f.frags));
    if (frags != client.last_frags) {
        MessageWriter w(level.reliable_datagram, level.protocol);
        w.byte(svc_updatefrags);
        w.byte(0);
        w.shrt(frags);
        client.last_frags = frags;
    }
    client.message.insert(client.message.end(), level.reliable_datagram.begin(),
                          level.reliable_datagram.end());
    level.reliable_datagram.clear();

    std::vector<uint8_t>& datagram = blocks_[0];
    datagram.clear();
    MessageWriter w(datagram, level.protocol);
    w.byte(svc_time);
    w.flt(float(level.game.time));
    write_client_data(level, kPlayer, datagram, true);
    write_entities(level, kPlayer, datagram);
    datagram.insert(datagram.end(), level.datagram.begin(), level.datagram.end());
    used_blocks_ = 1;
    if (!client.message.empty()) {
        blocks_[1].clear();
        blocks_[1].swap(client.message);
        used_blocks_ = 2;
    }
    // Muzzle flashes last one frame.
    for (uint32_t e = 1; e < vm.num_edicts(); ++e) {
        const int effects = int(vm.field_float(e, f.effects));
        if (effects & 2) vm.set_field_float(e, f.effects, float(effects & ~2));
    }
}

}  // namespace nq::server

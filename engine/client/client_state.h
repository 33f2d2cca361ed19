// The client state of demo playback: what the server's messages have said (level, precache
// lists, entities and their baselines, static entities, light styles, player data, scoreboard,
// intermission) and what the client derives from it for each rendered frame (interpolated
// entities, effects, particles, dynamic lights). Plain C++: no rendering, no sound, no files:
// sounds and the CD track are recorded for the engine's sound system to take.
//
// Per frame the engine (or DemoPlayer) calls advance_clock(), applies the messages that are
// due (receive_block_angles() + apply()), then prepare_frame(); after that compute_view() and
// collect_visible_entities() produce what the renderer needs. A new svc_serverinfo (a new
// map, also in the middle of a demo) clears everything and increments generation(): the
// engine then loads model_names() and hands their ModelInfo to set_model_info().
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "client/beams.h"
#include "client/client_entity.h"
#include "client/client_random.h"
#include "client/dynamic_lights.h"
#include "client/items.h"
#include "client/lightstyles.h"
#include "client/model_info.h"
#include "client/particle_effects.h"
#include "client/particle_system.h"
#include "client/screen_flashes.h"
#include "client/sound_events.h"
#include "client/temp_entity_buffer.h"
#include "formats/server_message.h"

namespace nq {

inline constexpr int kSignonStages = 4;  // signed on: entities flow, frames render
inline constexpr int kMaxScoreboard = 16;
inline constexpr int kMaxStats = 32;

// Indices into PlayerState::stats (svc_updatestat numbering).
enum Stat : int {
    kStatHealth = 0,
    kStatFrags = 1,
    kStatWeapon = 2,  // model index of the view (weapon) model
    kStatAmmo = 3,
    kStatArmor = 4,
    kStatWeaponFrame = 5,
    kStatShells = 6,
    kStatNails = 7,
    kStatRockets = 8,
    kStatCells = 9,
    kStatActiveWeapon = 10,
    kStatTotalSecrets = 11,
    kStatTotalMonsters = 12,
    kStatSecrets = 13,
    kStatMonsters = 14,
};

enum class LerpMode {
    Interpolate,  // playback: entities and view angles blend between the last two messages
    Snap,         // timedemo: client time jumps to the latest message; nothing blends
};

enum class Intermission : int { None = 0, Intermission = 1, Finale = 2, Cutscene = 3 };

struct ClientSettings {
    size_t particle_capacity = kDefaultParticleCapacity;
    uint64_t random_seed = 1;
    float gravity = 800;  // sv_gravity, for particle physics
    // Spawn a client-side s_explod.spr for TE_EXPLOSION, as QuakeWorld clients do. Off by
    // default: NetQuake progs already send the explosion sprite as an entity (demo2.dem does).
    bool explosion_sprites = false;
};

inline constexpr int kGameTypeDeathmatch = 1;  // LevelInfo::game_type (0: single player, coop)

struct LevelInfo {
    int protocol = 0;
    uint32_t protocol_flags = 0;
    int max_clients = 0;
    int game_type = 0;
    std::string level_name;
};

struct PlayerState {
    int view_height = protocol::kDefaultViewHeight;
    int ideal_pitch = 0;
    Vec3 punch_angles{};
    std::array<Vec3, 2> message_velocity{};  // [0] latest clientdata, [1] the one before
    Vec3 velocity{};                         // interpolated for this frame
    int32_t items = 0;
    // Client time at which each items bit was last switched on (Quake's item_gettime): the
    // inventory flashes a weapon for a second after it is picked up.
    std::array<double, kItemBits> item_times{};
    bool on_ground = false;
    bool in_water = false;
    int weapon_alpha = 0;  // encoded as decode_alpha() expects
    std::array<int32_t, kMaxStats> stats{};
    Vec3 set_angles{};                        // the last svc_setangle
    std::array<Vec3, 2> block_view_angles{};  // demo block headers: [0] latest, [1] before
    Vec3 view_angles{};                       // interpolated for this frame
};

struct ScoreboardEntry {
    std::string name;
    int frags = 0;
    int colors = 0;  // top << 4 | bottom
};

// Models the client draws itself; appended to the precache list when the server lacks them.
struct ClientModels {
    int bolt = 0, bolt2 = 0, bolt3 = 0, beam = 0, explosion = 0;
};

struct ExplosionSprite {
    Vec3 origin{};
    double start = -1;  // < 0: free
};
inline constexpr size_t kMaxExplosionSprites = 32;

class ClientState {
  public:
    explicit ClientState(const ClientSettings& settings = {});
    ClientState(const ClientState&) = delete;  // effects hold references into the state
    ClientState& operator=(const ClientState&) = delete;

    // ---- receiving messages
    // Applies one decoded server message. Returns a description of the problem when the
    // message cannot be applied (an entity, model, client or style number out of range); the
    // state is unchanged by the failing message.
    std::optional<std::string> apply(const ServerMessage& message);
    // The view angles of a demo block header, received before the block's messages.
    void receive_block_angles(const Vec3& angles);
    // The view angles of a player at the controls: used as they are, not blended.
    void set_view_angles(const Vec3& angles) { player_.block_view_angles = {angles, angles}; }

    // ---- the frame
    void advance_clock(double frame_time);  // old_time = time; time += frame_time
    void set_time(double time);             // for engines (and tests) that own the clock
    // Settles the frame's time and interpolation fraction, moves entities, runs effects,
    // trails, dynamic lights, beams and particles. No heap allocation.
    void prepare_frame(LerpMode mode);

    // ---- connection and level
    int signon() const { return signon_; }
    bool signed_on() const { return signon_ >= kSignonStages; }
    bool disconnected() const { return disconnected_; }
    uint32_t generation() const { return generation_; }  // +1 on every svc_serverinfo
    const LevelInfo& level() const { return level_; }
    // Model names by model index: [0] is empty, 1..precache_model_count()-1 the server's
    // precache list (1 = the map), then the ClientModels the server did not list.
    std::span<const std::string> model_names() const { return model_names_; }
    size_t precache_model_count() const { return precache_models_; }
    const ClientModels& client_models() const { return client_models_; }
    std::span<const std::string> sound_names() const { return sound_names_; }
    // Model information aligned with model_names() (missing entries count as unknown).
    void set_model_info(std::vector<ModelInfo> info);
    const ModelInfo& model_info(int index) const;

    // ---- time
    double time() const { return time_; }
    double old_time() const { return old_time_; }
    double message_time(int i) const { return message_times_[i & 1]; }  // 0 latest, 1 before
    float lerp_fraction() const { return lerp_fraction_; }

    // ---- entities
    int view_entity() const { return view_entity_; }
    const ClientEntity* entity(int number) const;  // nullptr beyond the highest number seen
    size_t entity_slots() const { return entities_.size(); }
    std::span<const StaticEntity> static_entities() const { return statics_; }
    std::span<const TempModelEntity> temp_entities() const { return temp_entities_.entities(); }
    const AnimationTracker& view_model_animation() const { return view_model_anim_; }

    // ---- the player
    const PlayerState& player() const { return player_; }
    std::span<const ScoreboardEntry> scoreboard() const { return scoreboard_; }
    Intermission intermission() const { return intermission_; }
    double completed_time() const { return completed_time_; }
    bool paused() const { return paused_; }
    // Damage and bonus flashes and the pain face (svc_damage, the stuffed "bf" command).
    const ScreenFlashes& flashes() const { return flashes_; }

    // ---- effects
    const LightStyles& light_styles() const { return light_styles_; }
    std::span<const float, kMaxLightStyles> light_style_values() const { return style_values_; }
    const ParticleSystem& particles() const { return particles_; }
    const DynamicLights& dynamic_lights() const { return dlights_; }
    const Beams& beams() const { return beams_; }
    std::span<const ExplosionSprite> explosion_sprites() const { return explosions_; }
    const std::string& skybox() const { return skybox_; }
    const svc::Fog& fog() const { return fog_; }

    // ---- text for the console and the command buffer (the engine drains these)
    std::vector<std::string> take_console_text() { return std::exchange(console_text_, {}); }
    std::vector<std::string> take_center_prints() { return std::exchange(center_prints_, {}); }
    std::vector<std::string> take_stuff_text() { return std::exchange(stuff_text_, {}); }

    // ---- sounds (the engine's sound system plays them)
    // Sounds started, stopped or placed since clear_sound_events(); a new level drops those of
    // the level before.
    std::span<const SoundEvent> sound_events() const { return sound_events_.events(); }
    void clear_sound_events() { sound_events_.clear(); }
    // The last svc_cdtrack: its track, and a count of them so a repeated track is seen too.
    int cd_track() const { return cd_track_; }
    uint32_t cd_track_messages() const { return cd_track_messages_; }

    // ---- bookkeeping
    uint32_t message_count(int kind) const;  // per message kind, ignored kinds included
    const std::vector<std::string>& warnings() const { return warnings_; }

  private:
    // client_state.cpp
    void clear_for_new_level();
    void add_client_models();
    ClientEntity* entity_slot(int number);  // grows the table; nullptr when out of range
    void warn(std::string text);

    // client_parse.cpp
    std::optional<std::string> on_server_info(const svc::ServerInfo& m);
    void on_client_data(const svc::ClientData& m);
    std::optional<std::string> on_signon(int stage);
    std::optional<std::string> on_light_style(const svc::LightStyle& m);
    ScoreboardEntry* score_entry(int client);  // nullptr when outside 0..max_clients-1
    std::optional<std::string> on_stat(const svc::UpdateStat& m);
    void on_intermission(Intermission kind, const std::string* text);
    void on_stuff_text(const std::string& text);

    // entity_messages.cpp
    std::optional<std::string> on_baseline(int number, const EntityState& state, bool has_alpha);
    std::optional<std::string> on_static(const EntityState& state);
    std::optional<std::string> on_entity_update(const svc::EntityUpdate& m);
    std::optional<std::string> check_model_index(int model) const;
    void change_model(ClientEntity& e, int model);

    // temp_entities.cpp
    std::optional<std::string> on_temp_entity(const svc::TempEntity& m);
    void on_particle(const svc::Particle& m);
    void spawn_explosion_sprite(const Vec3& origin);

    // client_relink.cpp
    float settle_lerp_point(LerpMode mode);
    void lerp_player(float frac);
    void relink_entities(float frac);
    void relink_entity(int number, ClientEntity& e, float frac);
    void entity_effects(int number, ClientEntity& e);
    void model_trail(int number, const ModelInfo& info, const Vec3& from, const Vec3& to);
    void build_temp_entities();

    ClientSettings settings_;
    ClientRandom random_;
    ParticleSystem particles_;
    ParticleEffects effects_;
    DynamicLights dlights_;
    Beams beams_;
    TempEntityBuffer temp_entities_;
    std::array<ExplosionSprite, kMaxExplosionSprites> explosions_{};
    LightStyles light_styles_;
    std::array<float, kMaxLightStyles> style_values_{};

    int signon_ = 0;
    bool disconnected_ = false;
    uint32_t generation_ = 0;
    LevelInfo level_;
    std::vector<std::string> model_names_;
    size_t precache_models_ = 1;
    ClientModels client_models_;
    std::vector<std::string> sound_names_;
    std::vector<ModelInfo> model_info_;

    double time_ = 0, old_time_ = 0;
    std::array<double, 2> message_times_{};
    float lerp_fraction_ = 1;

    int view_entity_ = 0;
    std::vector<ClientEntity> entities_;
    std::vector<StaticEntity> statics_;
    AnimationTracker view_model_anim_;

    PlayerState player_;
    std::vector<ScoreboardEntry> scoreboard_;
    Intermission intermission_ = Intermission::None;
    double completed_time_ = 0;
    bool paused_ = false;
    ScreenFlashes flashes_;
    std::string skybox_;
    svc::Fog fog_;

    SoundEventQueue sound_events_;
    int cd_track_ = 0;
    uint32_t cd_track_messages_ = 0;

    std::vector<std::string> console_text_, center_prints_, stuff_text_;
    std::array<uint32_t, 256> message_counts_{};
    std::vector<std::string> warnings_;
};

}  // namespace nq

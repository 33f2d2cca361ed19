// Decoded server-to-client messages: one plain struct per svc message kind, held in the
// ServerMessage variant. Produced by message_decoder.h, consumed by message_encoder.h.
//
// Conventions shared by every struct:
//  - Coordinates and angles are floats in world units and degrees, exactly as the protocol's
//    encoding yields them (their wire form depends on the protocol and RMQ flags).
//  - Where a message carries a bit mask (fast updates, clientdata, sound, baseline2), the mask
//    is kept as sent and is authoritative: it says which fields were on the wire. A field that
//    was not sent holds the protocol's default (0, or the documented default next to it). The
//    encoder refuses values that the mask cannot carry, so nothing is silently dropped.
//  - Byte-sized wire fields are held in `int` for convenience; the encoder range-checks them.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "formats/protocol.h"

namespace nq {

using Vec3 = std::array<float, 3>;

// Kind number used for fast entity updates (they have no svc number: their first byte has bit
// 7 set). Chosen outside 0..127 so kinds can index one table.
inline constexpr int kEntityUpdateKind = 128;

// The entity fields of svc_spawnbaseline(2) and svc_spawnstatic(2).
struct EntityState {
    int model = 0;  // model precache index (byte, or uint16 with B_LARGEMODEL)
    int frame = 0;  // byte, or uint16 with B_LARGEFRAME
    int colormap = 0;
    int skin = 0;
    Vec3 origin{};
    Vec3 angles{};
    int alpha = 0;  // ENTALPHA encoded: 0 default, 1 invisible .. 255 opaque (B_ALPHA only)
    bool operator==(const EntityState&) const = default;
};

// The fields of svc_spawnstaticsound(2): an ambient sound looping at a fixed place.
struct StaticSoundFields {
    Vec3 origin{};
    int sound = 0;  // precache index: byte (version 1) or uint16 (version 2)
    int volume = 0;
    float attenuation = 0;  // byte / 64
    bool operator==(const StaticSoundFields&) const = default;
};

namespace svc {

struct Nop {
    static constexpr int kSvc = protocol::svc_nop;
    bool operator==(const Nop&) const = default;
};
struct Disconnect {
    static constexpr int kSvc = protocol::svc_disconnect;
    bool operator==(const Disconnect&) const = default;
};
struct UpdateStat {
    static constexpr int kSvc = protocol::svc_updatestat;
    int stat = 0;  // byte: STAT_* index
    int32_t value = 0;
    bool operator==(const UpdateStat&) const = default;
};
struct Version {
    static constexpr int kSvc = protocol::svc_version;
    int32_t protocol = 0;  // switches the stream's protocol, like serverinfo
    bool operator==(const Version&) const = default;
};
struct SetView {
    static constexpr int kSvc = protocol::svc_setview;
    int entity = 0;  // int16
    bool operator==(const SetView&) const = default;
};
struct Sound {
    static constexpr int kSvc = protocol::svc_sound;
    int field_mask = 0;                                      // SND_* bits as sent
    int volume = protocol::kDefaultSoundVolume;              // byte, SND_VOLUME
    float attenuation = protocol::kDefaultSoundAttenuation;  // byte / 64, SND_ATTENUATION
    int entity = 0;   // 13 bits, or uint16 with SND_LARGEENTITY
    int channel = 0;  // 3 bits, or a byte with SND_LARGEENTITY
    int sound = 0;    // sound precache index: byte, or uint16 with SND_LARGESOUND
    Vec3 origin{};
    bool operator==(const Sound&) const = default;
};
struct Time {
    static constexpr int kSvc = protocol::svc_time;
    float time = 0;  // server time in seconds of the frame that follows
    bool operator==(const Time&) const = default;
};
struct Print {
    static constexpr int kSvc = protocol::svc_print;
    std::string text;
    bool operator==(const Print&) const = default;
};
struct StuffText {
    static constexpr int kSvc = protocol::svc_stufftext;
    std::string text;  // console commands, normally newline-terminated
    bool operator==(const StuffText&) const = default;
};
struct SetAngle {
    static constexpr int kSvc = protocol::svc_setangle;
    Vec3 angles{};  // protocol angle encoding
    bool operator==(const SetAngle&) const = default;
};
struct ServerInfo {
    static constexpr int kSvc = protocol::svc_serverinfo;
    int32_t protocol = protocol::kNetQuake;
    uint32_t protocol_flags = 0;  // only on the wire for protocol 999
    int max_clients = 1;
    int game_type = 0;  // 0 coop, 1 deathmatch
    std::string level_name;
    std::vector<std::string> models;  // precache list from index 1; models[0] is the world
    std::vector<std::string> sounds;  // precache list from index 1
    bool operator==(const ServerInfo&) const = default;
};
struct LightStyle {
    static constexpr int kSvc = protocol::svc_lightstyle;
    int style = 0;
    std::string pattern;  // 'a' (dark) .. 'z' (bright), one letter per 0.1 s
    bool operator==(const LightStyle&) const = default;
};
struct UpdateName {
    static constexpr int kSvc = protocol::svc_updatename;
    int client = 0;
    std::string name;
    bool operator==(const UpdateName&) const = default;
};
struct UpdateFrags {
    static constexpr int kSvc = protocol::svc_updatefrags;
    int client = 0;
    int frags = 0;  // int16
    bool operator==(const UpdateFrags&) const = default;
};
struct ClientData {
    static constexpr int kSvc = protocol::svc_clientdata;
    uint32_t bits = protocol::SU_ITEMS;              // SU_* bits as sent (extension bytes included)
    int view_height = protocol::kDefaultViewHeight;  // int8, SU_VIEWHEIGHT
    int ideal_pitch = 0;                             // int8, SU_IDEALPITCH
    std::array<int, 3> punch_angle{};                // int8 degrees, SU_PUNCH1..3
    std::array<int, 3> velocity{};                   // int8 * 16, SU_VELOCITY1..3
    int32_t items = 0;                               // always sent, whatever SU_ITEMS says
    int weapon_frame = 0;  // SU_WEAPONFRAME low byte, SU_WEAPONFRAME2 high byte
    int armor = 0;         // SU_ARMOR / SU_ARMOR2
    int weapon = 0;        // weapon model index: SU_WEAPON / SU_WEAPON2
    int health = 0;        // int16, always sent
    int ammo = 0;          // always-sent low byte, SU_AMMO2 high byte
    int shells = 0;        // always-sent low bytes, SU_SHELLS2 .. SU_CELLS2 high bytes
    int nails = 0;
    int rockets = 0;
    int cells = 0;
    int active_weapon = 0;  // byte, always sent
    int weapon_alpha = 0;   // ENTALPHA encoded, SU_WEAPONALPHA
    bool on_ground() const { return (bits & protocol::SU_ONGROUND) != 0; }
    bool in_water() const { return (bits & protocol::SU_INWATER) != 0; }
    bool operator==(const ClientData&) const = default;
};
struct StopSound {
    static constexpr int kSvc = protocol::svc_stopsound;
    int entity = 0;   // 13 bits
    int channel = 0;  // 3 bits
    bool operator==(const StopSound&) const = default;
};
struct UpdateColors {
    static constexpr int kSvc = protocol::svc_updatecolors;
    int client = 0;
    int colors = 0;  // top colour << 4 | bottom colour
    bool operator==(const UpdateColors&) const = default;
};
struct Particle {
    static constexpr int kSvc = protocol::svc_particle;
    Vec3 origin{};
    Vec3 direction{};  // int8 / 16 per axis
    int count = 0;     // byte; 255 means 1024 particles (an explosion)
    int color = 0;
    bool operator==(const Particle&) const = default;
};
struct Damage {
    static constexpr int kSvc = protocol::svc_damage;
    int armor = 0;  // damage taken by armour
    int blood = 0;  // damage taken by health
    Vec3 from{};
    bool operator==(const Damage&) const = default;
};
struct SpawnStatic {
    static constexpr int kSvc = protocol::svc_spawnstatic;
    EntityState state;  // byte model and frame, no alpha
    bool operator==(const SpawnStatic&) const = default;
};
struct SpawnBaseline {
    static constexpr int kSvc = protocol::svc_spawnbaseline;
    int entity = 0;  // int16
    EntityState state;
    bool operator==(const SpawnBaseline&) const = default;
};
struct TempEntity {
    static constexpr int kSvc = protocol::svc_temp_entity;
    int type = 0;          // protocol::TE_*
    Vec3 origin{};         // position; for beams the start point
    int entity = 0;        // beams only: int16 owner entity
    Vec3 end{};            // beams only
    int color_start = 0;   // TE_EXPLOSION2 only
    int color_length = 0;  // TE_EXPLOSION2 only
    bool operator==(const TempEntity&) const = default;
};
struct SetPause {
    static constexpr int kSvc = protocol::svc_setpause;
    int paused = 0;
    bool operator==(const SetPause&) const = default;
};
struct SignonNum {
    static constexpr int kSvc = protocol::svc_signonnum;
    int stage = 0;
    bool operator==(const SignonNum&) const = default;
};
struct CenterPrint {
    static constexpr int kSvc = protocol::svc_centerprint;
    std::string text;
    bool operator==(const CenterPrint&) const = default;
};
struct KilledMonster {
    static constexpr int kSvc = protocol::svc_killedmonster;
    bool operator==(const KilledMonster&) const = default;
};
struct FoundSecret {
    static constexpr int kSvc = protocol::svc_foundsecret;
    bool operator==(const FoundSecret&) const = default;
};
struct SpawnStaticSound {
    static constexpr int kSvc = protocol::svc_spawnstaticsound;
    StaticSoundFields fields;
    bool operator==(const SpawnStaticSound&) const = default;
};
struct Intermission {
    static constexpr int kSvc = protocol::svc_intermission;
    bool operator==(const Intermission&) const = default;
};
struct Finale {
    static constexpr int kSvc = protocol::svc_finale;
    std::string text;
    bool operator==(const Finale&) const = default;
};
struct CdTrack {
    static constexpr int kSvc = protocol::svc_cdtrack;
    int track = 0;
    int loop_track = 0;
    bool operator==(const CdTrack&) const = default;
};
struct SellScreen {
    static constexpr int kSvc = protocol::svc_sellscreen;
    bool operator==(const SellScreen&) const = default;
};
struct Cutscene {
    static constexpr int kSvc = protocol::svc_cutscene;
    std::string text;
    bool operator==(const Cutscene&) const = default;
};
// FitzQuake extensions (decoded under every protocol, as FitzQuake-family clients do).
struct Skybox {
    static constexpr int kSvc = protocol::svc_skybox;
    std::string name;  // empty: back to the map's own sky
    bool operator==(const Skybox&) const = default;
};
struct Bf {
    static constexpr int kSvc = protocol::svc_bf;  // the bonus flash
    bool operator==(const Bf&) const = default;
};
struct Fog {
    static constexpr int kSvc = protocol::svc_fog;
    float density = 0;    // byte / 255
    Vec3 color{};         // bytes / 255
    float fade_time = 0;  // int16 / 100 seconds
    bool operator==(const Fog&) const = default;
};
struct SpawnBaseline2 {
    static constexpr int kSvc = protocol::svc_spawnbaseline2;
    int entity = 0;  // int16
    int flags = 0;   // B_* bits as sent
    EntityState state;
    bool operator==(const SpawnBaseline2&) const = default;
};
struct SpawnStatic2 {
    static constexpr int kSvc = protocol::svc_spawnstatic2;
    int flags = 0;  // B_* bits as sent
    EntityState state;
    bool operator==(const SpawnStatic2&) const = default;
};
struct SpawnStaticSound2 {
    static constexpr int kSvc = protocol::svc_spawnstaticsound2;
    StaticSoundFields fields;
    bool operator==(const SpawnStaticSound2&) const = default;
};

// A fast entity update (first byte has bit 7 set). Fields whose bit is clear were not sent:
// the entity keeps its baseline value for them; here they hold 0.
struct EntityUpdate {
    static constexpr int kSvc = kEntityUpdateKind;
    uint32_t bits = protocol::U_SIGNAL;  // U_* bits as sent, extension bytes included
    int entity = 0;                      // byte, or int16 with U_LONGENTITY
    int model = 0;                       // U_MODEL low byte | U_MODEL2 high byte
    int frame = 0;                       // U_FRAME low byte | U_FRAME2 high byte
    int colormap = 0;                    // U_COLORMAP
    int skin = 0;                        // U_SKIN
    int effects = 0;                     // U_EFFECTS (EF_* bits)
    Vec3 origin{};                       // U_ORIGIN1..3 per axis
    Vec3 angles{};                       // U_ANGLE1..3 per axis
    int alpha = 0;                       // U_ALPHA, ENTALPHA encoded
    int scale = 0;                       // U_SCALE, RMQ scale byte (16 = 1.0)
    float lerp_finish = 0;               // U_LERPFINISH: seconds until the next think, byte / 255
    bool has(uint32_t bit) const { return (bits & bit) != 0; }
    bool operator==(const EntityUpdate&) const = default;
};

}  // namespace svc

// The most frequent kinds come first: unoptimised builds construct early alternatives faster.
using ServerMessage =
    std::variant<svc::EntityUpdate, svc::Time, svc::ClientData, svc::Sound, svc::Nop,
                 svc::Disconnect, svc::UpdateStat, svc::Version, svc::SetView, svc::Print,
                 svc::StuffText, svc::SetAngle, svc::ServerInfo, svc::LightStyle, svc::UpdateName,
                 svc::UpdateFrags, svc::StopSound, svc::UpdateColors, svc::Particle, svc::Damage,
                 svc::SpawnStatic, svc::SpawnBaseline, svc::TempEntity, svc::SetPause,
                 svc::SignonNum, svc::CenterPrint, svc::KilledMonster, svc::FoundSecret,
                 svc::SpawnStaticSound, svc::Intermission, svc::Finale, svc::CdTrack,
                 svc::SellScreen, svc::Cutscene, svc::Skybox, svc::Bf, svc::Fog,
                 svc::SpawnBaseline2, svc::SpawnStatic2, svc::SpawnStaticSound2>;

// The svc number of a message, or kEntityUpdateKind for a fast entity update.
inline int message_kind(const ServerMessage& m) {
    return std::visit([](const auto& v) { return std::decay_t<decltype(v)>::kSvc; }, m);
}

// "svc_time", ..., or "entity_update" for kEntityUpdateKind.
inline std::string_view message_kind_name(int kind) {
    return kind == kEntityUpdateKind ? std::string_view("entity_update") : protocol::svc_name(kind);
}

}  // namespace nq

// Quake server-to-client protocol constants: NetQuake (15), FitzQuake (666) and RMQ (999).
// Facts only (message numbers, bit assignments, encodings); the decoder and encoder that use
// them live in message_decoder.* and message_encoder.*.
#pragma once

#include <cstdint>
#include <iterator>
#include <string_view>

namespace nq::protocol {

inline constexpr int kNetQuake = 15;
inline constexpr int kFitzQuake = 666;
inline constexpr int kRmq = 999;

inline constexpr bool is_supported(int32_t p) {
    return p == kNetQuake || p == kFitzQuake || p == kRmq;
}
// FitzQuake and RMQ share the extended update/clientdata bits and the larger limits.
inline constexpr bool has_fitz_extensions(int p) {
    return p == kFitzQuake || p == kRmq;
}

// RMQ (999) protocol flags, sent after the protocol number in svc_serverinfo. They select the
// wire encoding of coordinates and angles; when several coordinate flags are set the first one
// in this order wins: FLOATCOORD, INT32COORD, 24BITCOORD (likewise FLOATANGLE before SHORTANGLE).
inline constexpr uint32_t PRFL_SHORTANGLE = 1u << 1;  // angle = int16 * 360/65536
inline constexpr uint32_t PRFL_FLOATANGLE = 1u << 2;  // angle = float32 degrees
inline constexpr uint32_t PRFL_24BITCOORD = 1u << 3;  // coord = int16 + uint8/255
inline constexpr uint32_t PRFL_FLOATCOORD = 1u << 4;  // coord = float32
inline constexpr uint32_t PRFL_EDICTSCALE = 1u << 5;  // entities may carry U_SCALE
inline constexpr uint32_t PRFL_ALPHASANITY = 1u << 6;
inline constexpr uint32_t PRFL_INT32COORD = 1u << 7;  // coord = int32 / 16
inline constexpr uint32_t PRFL_MOREFLAGS = 1u << 31;  // reserved, never used by any engine
inline constexpr uint32_t kKnownProtocolFlags =
    PRFL_SHORTANGLE | PRFL_FLOATANGLE | PRFL_24BITCOORD | PRFL_FLOATCOORD | PRFL_EDICTSCALE |
    PRFL_ALPHASANITY | PRFL_INT32COORD;

// Where a message stream stands: which protocol and flags its coordinates and angles use.
// Both the decoder and the encoder switch it on svc_serverinfo (and svc_version).
struct ProtocolState {
    int protocol = kNetQuake;
    uint32_t flags = 0;  // PRFL_* bits; always 0 outside protocol 999
    bool operator==(const ProtocolState&) const = default;
};

// Server message numbers (the first byte of each message; bit 7 set means a fast entity update).
enum Svc : uint8_t {
    svc_bad = 0,
    svc_nop = 1,
    svc_disconnect = 2,
    svc_updatestat = 3,
    svc_version = 4,
    svc_setview = 5,
    svc_sound = 6,
    svc_time = 7,
    svc_print = 8,
    svc_stufftext = 9,
    svc_setangle = 10,
    svc_serverinfo = 11,
    svc_lightstyle = 12,
    svc_updatename = 13,
    svc_updatefrags = 14,
    svc_clientdata = 15,
    svc_stopsound = 16,
    svc_updatecolors = 17,
    svc_particle = 18,
    svc_damage = 19,
    svc_spawnstatic = 20,
    svc_spawnbinary = 21,  // obsolete: no engine ever parsed it, a decoder must reject it
    svc_spawnbaseline = 22,
    svc_temp_entity = 23,
    svc_setpause = 24,
    svc_signonnum = 25,
    svc_centerprint = 26,
    svc_killedmonster = 27,
    svc_foundsecret = 28,
    svc_spawnstaticsound = 29,
    svc_intermission = 30,
    svc_finale = 31,
    svc_cdtrack = 32,
    svc_sellscreen = 33,
    svc_cutscene = 34,
    // FitzQuake additions (35, 36, 38, 39 are unassigned in 666/999).
    svc_skybox = 37,
    svc_bf = 40,
    svc_fog = 41,
    svc_spawnbaseline2 = 42,
    svc_spawnstatic2 = 43,
    svc_spawnstaticsound2 = 44,
};

// Printable name of a message number ("svc_time"); "svc_unknown" for unassigned numbers.
inline constexpr std::string_view svc_name(int svc) {
    constexpr std::string_view kNames[] = {"svc_bad",
                                           "svc_nop",
                                           "svc_disconnect",
                                           "svc_updatestat",
                                           "svc_version",
                                           "svc_setview",
                                           "svc_sound",
                                           "svc_time",
                                           "svc_print",
                                           "svc_stufftext",
                                           "svc_setangle",
                                           "svc_serverinfo",
                                           "svc_lightstyle",
                                           "svc_updatename",
                                           "svc_updatefrags",
                                           "svc_clientdata",
                                           "svc_stopsound",
                                           "svc_updatecolors",
                                           "svc_particle",
                                           "svc_damage",
                                           "svc_spawnstatic",
                                           "svc_spawnbinary",
                                           "svc_spawnbaseline",
                                           "svc_temp_entity",
                                           "svc_setpause",
                                           "svc_signonnum",
                                           "svc_centerprint",
                                           "svc_killedmonster",
                                           "svc_foundsecret",
                                           "svc_spawnstaticsound",
                                           "svc_intermission",
                                           "svc_finale",
                                           "svc_cdtrack",
                                           "svc_sellscreen",
                                           "svc_cutscene",
                                           "svc_unknown",
                                           "svc_unknown",
                                           "svc_skybox",
                                           "svc_unknown",
                                           "svc_unknown",
                                           "svc_bf",
                                           "svc_fog",
                                           "svc_spawnbaseline2",
                                           "svc_spawnstatic2",
                                           "svc_spawnstaticsound2"};
    if (svc < 0 || svc >= static_cast<int>(std::size(kNames))) return "svc_unknown";
    return kNames[svc];
}

// Fast entity update bits. The first byte has bit 7 (U_SIGNAL) set; the rest of the bits
// follow in up to three more bytes (U_MOREBITS, then U_EXTEND1 and U_EXTEND2 in 666/999).
inline constexpr uint32_t U_MOREBITS = 1u << 0;
inline constexpr uint32_t U_ORIGIN1 = 1u << 1;
inline constexpr uint32_t U_ORIGIN2 = 1u << 2;
inline constexpr uint32_t U_ORIGIN3 = 1u << 3;
inline constexpr uint32_t U_ANGLE2 = 1u << 4;
inline constexpr uint32_t U_NOLERP = 1u << 5;  // a.k.a. U_STEP: MOVETYPE_STEP, no data
inline constexpr uint32_t U_FRAME = 1u << 6;
inline constexpr uint32_t U_SIGNAL = 1u << 7;  // marks the byte as an update, no data
inline constexpr uint32_t U_ANGLE1 = 1u << 8;
inline constexpr uint32_t U_ANGLE3 = 1u << 9;
inline constexpr uint32_t U_MODEL = 1u << 10;
inline constexpr uint32_t U_COLORMAP = 1u << 11;
inline constexpr uint32_t U_SKIN = 1u << 12;
inline constexpr uint32_t U_EFFECTS = 1u << 13;
inline constexpr uint32_t U_LONGENTITY = 1u << 14;  // entity number is int16, not a byte
inline constexpr uint32_t U_EXTEND1 = 1u << 15;     // 666/999: bits 16..23 follow
inline constexpr uint32_t U_TRANS = 1u << 15;       // same bit in Nehahra's protocol 15 hack
inline constexpr uint32_t U_ALPHA = 1u << 16;       // byte, ENTALPHA encoded
inline constexpr uint32_t U_FRAME2 = 1u << 17;      // byte, frame bits 8..15
inline constexpr uint32_t U_MODEL2 = 1u << 18;      // byte, model index bits 8..15
inline constexpr uint32_t U_LERPFINISH = 1u << 19;  // byte, seconds * 255
inline constexpr uint32_t U_SCALE = 1u << 20;       // byte, RMQ entity scale (16 = 1.0)
inline constexpr uint32_t U_UNUSED21 = 1u << 21;
inline constexpr uint32_t U_UNUSED22 = 1u << 22;
inline constexpr uint32_t U_EXTEND2 = 1u << 23;  // 666/999: bits 24..31 follow (all unused)

// svc_clientdata bits: an int16 of bits, extended in 666/999 by SU_EXTEND1/SU_EXTEND2 bytes.
inline constexpr uint32_t SU_VIEWHEIGHT = 1u << 0;
inline constexpr uint32_t SU_IDEALPITCH = 1u << 1;
inline constexpr uint32_t SU_PUNCH1 = 1u << 2;
inline constexpr uint32_t SU_PUNCH2 = 1u << 3;
inline constexpr uint32_t SU_PUNCH3 = 1u << 4;
inline constexpr uint32_t SU_VELOCITY1 = 1u << 5;
inline constexpr uint32_t SU_VELOCITY2 = 1u << 6;
inline constexpr uint32_t SU_VELOCITY3 = 1u << 7;
inline constexpr uint32_t SU_UNUSED8 = 1u << 8;
inline constexpr uint32_t SU_ITEMS = 1u << 9;      // servers always set it; items are always sent
inline constexpr uint32_t SU_ONGROUND = 1u << 10;  // no data, the bit is the value
inline constexpr uint32_t SU_INWATER = 1u << 11;   // no data, the bit is the value
inline constexpr uint32_t SU_WEAPONFRAME = 1u << 12;
inline constexpr uint32_t SU_ARMOR = 1u << 13;
inline constexpr uint32_t SU_WEAPON = 1u << 14;
inline constexpr uint32_t SU_EXTEND1 = 1u << 15;  // bits 16..23 follow
inline constexpr uint32_t SU_WEAPON2 = 1u << 16;  // high bytes of the matching values
inline constexpr uint32_t SU_ARMOR2 = 1u << 17;
inline constexpr uint32_t SU_AMMO2 = 1u << 18;
inline constexpr uint32_t SU_SHELLS2 = 1u << 19;
inline constexpr uint32_t SU_NAILS2 = 1u << 20;
inline constexpr uint32_t SU_ROCKETS2 = 1u << 21;
inline constexpr uint32_t SU_CELLS2 = 1u << 22;
inline constexpr uint32_t SU_EXTEND2 = 1u << 23;  // bits 24..31 follow
inline constexpr uint32_t SU_WEAPONFRAME2 = 1u << 24;
inline constexpr uint32_t SU_WEAPONALPHA = 1u << 25;  // byte, ENTALPHA encoded
inline constexpr uint32_t SU_EXTEND3 = 1u << 31;      // reserved; no engine reads more bytes

inline constexpr int kDefaultViewHeight = 22;  // svc_clientdata without SU_VIEWHEIGHT

// svc_sound field mask.
inline constexpr uint8_t SND_VOLUME = 1u << 0;
inline constexpr uint8_t SND_ATTENUATION = 1u << 1;
inline constexpr uint8_t SND_LOOPING = 1u << 2;      // never sent; no data
inline constexpr uint8_t SND_LARGEENTITY = 1u << 3;  // entity uint16 + channel byte
inline constexpr uint8_t SND_LARGESOUND = 1u << 4;   // sound index uint16
inline constexpr int kDefaultSoundVolume = 255;
inline constexpr float kDefaultSoundAttenuation = 1.0f;

// Flags byte of svc_spawnbaseline2 / svc_spawnstatic2.
inline constexpr uint8_t B_LARGEMODEL = 1u << 0;  // model index uint16 instead of byte
inline constexpr uint8_t B_LARGEFRAME = 1u << 1;  // frame uint16 instead of byte
inline constexpr uint8_t B_ALPHA = 1u << 2;       // alpha byte follows

// svc_temp_entity kinds.
enum TempEntity : uint8_t {
    TE_SPIKE = 0,
    TE_SUPERSPIKE = 1,
    TE_GUNSHOT = 2,
    TE_EXPLOSION = 3,
    TE_TAREXPLOSION = 4,
    TE_LIGHTNING1 = 5,
    TE_LIGHTNING2 = 6,
    TE_WIZSPIKE = 7,
    TE_KNIGHTSPIKE = 8,
    TE_LIGHTNING3 = 9,
    TE_LAVASPLASH = 10,
    TE_TELEPORT = 11,
    TE_EXPLOSION2 = 12,  // position + colour start + colour length
    TE_BEAM = 13,        // Rogue's grappling beam
};
inline constexpr int kTempEntityKinds = 14;

// Beams carry an entity and two points; explosion2 carries colours; the rest one point.
inline constexpr bool is_beam(int te) {
    return te == TE_LIGHTNING1 || te == TE_LIGHTNING2 || te == TE_LIGHTNING3 || te == TE_BEAM;
}
inline constexpr std::string_view temp_entity_name(int te) {
    constexpr std::string_view kNames[] = {
        "TE_SPIKE",      "TE_SUPERSPIKE", "TE_GUNSHOT",    "TE_EXPLOSION",   "TE_TAREXPLOSION",
        "TE_LIGHTNING1", "TE_LIGHTNING2", "TE_WIZSPIKE",   "TE_KNIGHTSPIKE", "TE_LIGHTNING3",
        "TE_LAVASPLASH", "TE_TELEPORT",   "TE_EXPLOSION2", "TE_BEAM"};
    if (te < 0 || te >= kTempEntityKinds) return "TE_unknown";
    return kNames[te];
}

}  // namespace nq::protocol

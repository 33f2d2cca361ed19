#include "formats/message_encoder.h"

#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <type_traits>

namespace nq {
namespace {

using namespace protocol;

constexpr const char* kEncoderFile = "<encoder>";

[[noreturn]] void fail(std::string message) {
    throw FormatError(Error{kEncoderFile, 0, std::move(message)});
}

// Rounds v * scale to an integer in [lo, hi], or fails naming the field.
int64_t quantize(double v, double scale, int64_t lo, int64_t hi, const char* field) {
    double scaled = std::round(v * scale);
    if (!std::isfinite(v) || scaled < static_cast<double>(lo) || scaled > static_cast<double>(hi)) {
        fail(std::string(field) + " " + std::to_string(v) + " is outside the encodable range");
    }
    return static_cast<int64_t>(scaled);
}

// Little-endian output with range-checked integer fields.
class Writer {
  public:
    explicit Writer(std::vector<uint8_t>& out) : out_(out) {}

    void u8(int64_t v, const char* field) { put(checked(v, 0, 255, field), 1); }
    void i8(int64_t v, const char* field) { put(checked(v, -128, 127, field), 1); }
    void u16(int64_t v, const char* field) { put(checked(v, 0, 65535, field), 2); }
    void i16(int64_t v, const char* field) { put(checked(v, -32768, 32767, field), 2); }
    void i32(int64_t v, const char* field) {
        put(checked(v, std::numeric_limits<int32_t>::min(), std::numeric_limits<int32_t>::max(),
                    field),
            4);
    }
    void u32(uint32_t v) { put(v, 4); }
    void f32(float v, const char* field) {
        if (!std::isfinite(v)) fail(std::string(field) + " is NaN or infinite");
        uint32_t bits;
        std::memcpy(&bits, &v, sizeof bits);
        put(bits, 4);
    }
    void string(const std::string& s, const char* field) {
        if (s.find('\0') != std::string::npos) fail(std::string(field) + " contains a NUL byte");
        out_.insert(out_.end(), s.begin(), s.end());
        out_.push_back(0);
    }

  private:
    static int64_t checked(int64_t v, int64_t lo, int64_t hi, const char* field) {
        if (v < lo || v > hi) {
            fail(std::string(field) + " " + std::to_string(v) + " does not fit its field (" +
                 std::to_string(lo) + ".." + std::to_string(hi) + ")");
        }
        return v;
    }
    void put(int64_t v, int bytes) {
        for (int i = 0; i < bytes; ++i) out_.push_back(static_cast<uint8_t>(v >> (8 * i)));
    }

    std::vector<uint8_t>& out_;
};

// A field carried only when its bit is set must hold the decoder's default otherwise.
template <class T>
void require_default(bool sent, const T& value, const T& fallback, const char* field) {
    if (!sent && value != fallback)
        fail(std::string(field) + " is set but would not be sent (its bit is clear)");
}

// A value split into a low byte and a high byte, each sent only when its bit is set.
void require_split(bool low_sent, bool high_sent, int value, const char* field) {
    int mask = (low_sent ? 0xff : 0) | (high_sent ? 0xff00 : 0);
    if (value < 0 || (value & ~mask) != 0) {
        fail(std::string(field) + " " + std::to_string(value) +
             " cannot be carried by the bits that are set");
    }
}

class Encoder {
  public:
    Encoder(std::vector<uint8_t>& out, ProtocolState& state) : w_(out), state_(state) {}

    void encode(const ServerMessage& m) {
        std::visit([this](const auto& v) { encode_message(v); }, m);
    }

  private:
    uint32_t rmq_flags() const { return state_.protocol == kRmq ? state_.flags : 0; }
    bool fitz() const { return has_fitz_extensions(state_.protocol); }
    void require_fitz(const char* what) const {
        if (!fitz()) fail(std::string(what) + " needs protocol 666 or 999");
    }

    void svc(int number) { w_.u8(number, "svc"); }
    void coord(float v);
    void angle(float v);
    void coords(const Vec3& v) {
        for (float c : v) coord(c);
    }
    void angles(const Vec3& v) {
        for (float a : v) angle(a);
    }

    template <class Empty>
    requires std::is_empty_v<Empty>
    void encode_message(const Empty&) {
        svc(Empty::kSvc);  // messages without fields
    }
    void encode_message(const svc::UpdateStat& m) {
        svc(m.kSvc);
        w_.u8(m.stat, "stat");
        w_.i32(m.value, "value");
    }
    void encode_message(const svc::Version& m);
    void encode_message(const svc::SetView& m) {
        svc(m.kSvc);
        w_.i16(m.entity, "entity");
    }
    void encode_message(const svc::Sound& m);
    void encode_message(const svc::Time& m) {
        svc(m.kSvc);
        w_.f32(m.time, "time");
    }
    void encode_message(const svc::Print& m) { text(m.kSvc, m.text); }
    void encode_message(const svc::StuffText& m) { text(m.kSvc, m.text); }
    void encode_message(const svc::CenterPrint& m) { text(m.kSvc, m.text); }
    void encode_message(const svc::Finale& m) { text(m.kSvc, m.text); }
    void encode_message(const svc::Cutscene& m) { text(m.kSvc, m.text); }
    void encode_message(const svc::SetAngle& m) {
        svc(m.kSvc);
        angles(m.angles);
    }
    void encode_message(const svc::ServerInfo& m);
    void encode_message(const svc::LightStyle& m) {
        svc(m.kSvc);
        w_.u8(m.style, "style");
        w_.string(m.pattern, "pattern");
    }
    void encode_message(const svc::UpdateName& m) {
        svc(m.kSvc);
        w_.u8(m.client, "client");
        w_.string(m.name, "name");
    }
    void encode_message(const svc::UpdateFrags& m) {
        svc(m.kSvc);
        w_.u8(m.client, "client");
        w_.i16(m.frags, "frags");
    }
    void encode_message(const svc::ClientData& m);
    void encode_message(const svc::StopSound& m) {
        svc(m.kSvc);
        if (m.entity < 0 || m.entity >= 8192) fail("stopsound entity does not fit 13 bits");
        if (m.channel < 0 || m.channel >= 8) fail("stopsound channel does not fit 3 bits");
        w_.u16(m.entity << 3 | m.channel, "stopsound");
    }
    void encode_message(const svc::UpdateColors& m) {
        svc(m.kSvc);
        w_.u8(m.client, "client");
        w_.u8(m.colors, "colors");
    }
    void encode_message(const svc::Particle& m);
    void encode_message(const svc::Damage& m) {
        svc(m.kSvc);
        w_.u8(m.armor, "armor");
        w_.u8(m.blood, "blood");
        coords(m.from);
    }
    void encode_message(const svc::SpawnStatic& m) {
        svc(m.kSvc);
        entity_state(m.state, 0);
    }
    void encode_message(const svc::SpawnBaseline& m) {
        require_non_negative(m.entity);
        svc(m.kSvc);
        w_.i16(m.entity, "entity");
        entity_state(m.state, 0);
    }
    void encode_message(const svc::TempEntity& m);
    void encode_message(const svc::SetPause& m) {
        svc(m.kSvc);
        w_.u8(m.paused, "paused");
    }
    void encode_message(const svc::SignonNum& m) {
        svc(m.kSvc);
        w_.u8(m.stage, "signon stage");
    }
    void encode_message(const svc::SpawnStaticSound& m) {
        svc(m.kSvc);
        static_sound(m.fields, false);
    }
    void encode_message(const svc::CdTrack& m) {
        svc(m.kSvc);
        w_.u8(m.track, "track");
        w_.u8(m.loop_track, "loop track");
    }
    void encode_message(const svc::Skybox& m) {
        require_fitz("svc_skybox");
        text(m.kSvc, m.name);
    }
    void encode_message(const svc::Bf& m) {
        require_fitz("svc_bf");
        svc(m.kSvc);
    }
    void encode_message(const svc::Fog& m);
    void encode_message(const svc::SpawnBaseline2& m) {
        require_fitz("svc_spawnbaseline2");
        require_non_negative(m.entity);
        svc(m.kSvc);
        w_.i16(m.entity, "entity");
        w_.u8(m.flags, "baseline flags");
        entity_state(m.state, m.flags);
    }
    void encode_message(const svc::SpawnStatic2& m) {
        require_fitz("svc_spawnstatic2");
        svc(m.kSvc);
        w_.u8(m.flags, "baseline flags");
        entity_state(m.state, m.flags);
    }
    void encode_message(const svc::SpawnStaticSound2& m) {
        require_fitz("svc_spawnstaticsound2");
        svc(m.kSvc);
        static_sound(m.fields, true);
    }
    void encode_message(const svc::EntityUpdate& m);

    void text(int number, const std::string& s) {
        svc(number);
        w_.string(s, "text");
    }
    static void require_non_negative(int entity) {
        if (entity < 0) fail("negative entity number " + std::to_string(entity));
    }
    void client_data_bits(uint32_t bits);
    void client_data_classic(const svc::ClientData& m);
    void client_data_high_bytes(const svc::ClientData& m);
    void entity_state(const EntityState& s, int flags);
    void static_sound(const StaticSoundFields& s, bool large_index);
    uint32_t entity_update_bits(const svc::EntityUpdate& m) const;
    void entity_update_fields(const svc::EntityUpdate& m);
    void entity_update_fitz_fields(const svc::EntityUpdate& m);

    Writer w_;
    ProtocolState& state_;
};

// Inverse of the decoder's coordinate encodings, rounding to the nearest representable value.
void Encoder::coord(float v) {
    uint32_t flags = rmq_flags();
    if (flags & PRFL_FLOATCOORD) return w_.f32(v, "coordinate");
    if (!std::isfinite(v)) fail("coordinate is NaN or infinite");
    if (flags & PRFL_INT32COORD) {
        return w_.i32(quantize(v, 16.0, INT32_MIN, INT32_MAX, "coordinate"), "coordinate");
    }
    if (flags & PRFL_24BITCOORD) {
        double whole = std::floor(v);
        int64_t fraction = quantize(v - whole, 255.0, 0, 255, "coordinate fraction");
        if (fraction == 255) {  // rounds up to the next whole unit
            whole += 1;
            fraction = 0;
        }
        w_.i16(quantize(whole, 1.0, -32768, 32767, "coordinate"), "coordinate");
        return w_.u8(fraction, "coordinate fraction");
    }
    w_.i16(quantize(v, 8.0, -32768, 32767, "coordinate"), "coordinate");
}

// Angles wrap: any finite angle has an encoding (the nearest step modulo 360 degrees).
void Encoder::angle(float v) {
    uint32_t flags = rmq_flags();
    if (flags & PRFL_FLOATANGLE) return w_.f32(v, "angle");
    if (!std::isfinite(v)) fail("angle is NaN or infinite");
    double turn = std::fmod(static_cast<double>(v), 360.0);
    if (flags & PRFL_SHORTANGLE) {
        int64_t steps = static_cast<int64_t>(std::round(turn * 65536.0 / 360.0));
        return w_.u16(steps & 0xffff, "angle");
    }
    int64_t steps = static_cast<int64_t>(std::round(turn * 256.0 / 360.0));
    w_.u8(steps & 0xff, "angle");
}

void Encoder::encode_message(const svc::Version& m) {
    if (!is_supported(m.protocol)) fail("unsupported protocol " + std::to_string(m.protocol));
    svc(m.kSvc);
    w_.i32(m.protocol, "protocol");
    state_.protocol = m.protocol;
    if (m.protocol != kRmq) state_.flags = 0;
}

void Encoder::encode_message(const svc::Sound& m) {
    const int mask = m.field_mask;
    if (!fitz() && (mask & (SND_LARGEENTITY | SND_LARGESOUND))) {
        fail("SND_LARGEENTITY / SND_LARGESOUND need protocol 666 or 999");
    }
    require_default(mask & SND_VOLUME, m.volume, kDefaultSoundVolume, "sound volume");
    require_default(mask & SND_ATTENUATION, m.attenuation, kDefaultSoundAttenuation,
                    "sound attenuation");
    svc(m.kSvc);
    w_.u8(mask, "sound field mask");
    if (mask & SND_VOLUME) w_.u8(m.volume, "sound volume");
    if (mask & SND_ATTENUATION) {
        w_.u8(quantize(m.attenuation, 64.0, 0, 255, "sound attenuation"), "sound attenuation");
    }
    if (mask & SND_LARGEENTITY) {
        w_.u16(m.entity, "sound entity");
        w_.u8(m.channel, "sound channel");
    } else {
        if (m.entity < 0 || m.entity >= 8192) fail("sound entity needs SND_LARGEENTITY");
        if (m.channel < 0 || m.channel >= 8) fail("sound channel needs SND_LARGEENTITY");
        w_.u16(m.entity << 3 | m.channel, "sound entity");
    }
    if (mask & SND_LARGESOUND) {
        w_.u16(m.sound, "sound index");
    } else {
        w_.u8(m.sound, "sound index (without SND_LARGESOUND)");
    }
    coords(m.origin);
}

void Encoder::encode_message(const svc::ServerInfo& m) {
    if (!is_supported(m.protocol)) fail("unsupported protocol " + std::to_string(m.protocol));
    if (m.protocol != kRmq && m.protocol_flags != 0) fail("protocol flags need protocol 999");
    svc(m.kSvc);
    w_.i32(m.protocol, "protocol");
    if (m.protocol == kRmq) w_.u32(m.protocol_flags);
    w_.u8(m.max_clients, "max clients");
    w_.u8(m.game_type, "game type");
    w_.string(m.level_name, "level name");
    for (const auto* list : {&m.models, &m.sounds}) {
        for (const auto& name : *list) {
            if (name.empty()) fail("an empty precache name would end the list early");
            w_.string(name, "precache name");
        }
        w_.u8(0, "list end");
    }
    state_ = ProtocolState{m.protocol, m.protocol_flags};
}

void Encoder::client_data_bits(uint32_t bits) {
    if (!fitz() && bits > 0x7fff) fail("clientdata bits above 14 need protocol 666 or 999");
    if ((bits & 0xff0000) && !(bits & SU_EXTEND1)) fail("clientdata bits 16..23 need SU_EXTEND1");
    if ((bits & 0xff000000) && !(bits & SU_EXTEND2)) fail("clientdata bits 24..31 need SU_EXTEND2");
    w_.u16(bits & 0xffff, "clientdata bits");
    if (bits & SU_EXTEND1) w_.u8((bits >> 16) & 0xff, "clientdata bits");
    if (bits & SU_EXTEND2) w_.u8((bits >> 24) & 0xff, "clientdata bits");
}

void Encoder::encode_message(const svc::ClientData& m) {
    const uint32_t b = m.bits;
    require_default(b & SU_VIEWHEIGHT, m.view_height, kDefaultViewHeight, "view height");
    require_default(b & SU_IDEALPITCH, m.ideal_pitch, 0, "ideal pitch");
    for (int i = 0; i < 3; ++i) {
        require_default(b & (SU_PUNCH1 << i), m.punch_angle[i], 0, "punch angle");
        require_default(b & (SU_VELOCITY1 << i), m.velocity[i], 0, "velocity");
        if (m.velocity[i] % 16 != 0) fail("velocity is not a multiple of 16");
    }
    require_split(b & SU_WEAPONFRAME, b & SU_WEAPONFRAME2, m.weapon_frame, "weapon frame");
    require_split(b & SU_ARMOR, b & SU_ARMOR2, m.armor, "armor");
    require_split(b & SU_WEAPON, b & SU_WEAPON2, m.weapon, "weapon");
    require_split(true, b & SU_AMMO2, m.ammo, "ammo");
    require_split(true, b & SU_SHELLS2, m.shells, "shells");
    require_split(true, b & SU_NAILS2, m.nails, "nails");
    require_split(true, b & SU_ROCKETS2, m.rockets, "rockets");
    require_split(true, b & SU_CELLS2, m.cells, "cells");
    require_default(b & SU_WEAPONALPHA, m.weapon_alpha, 0, "weapon alpha");
    svc(m.kSvc);
    client_data_bits(b);
    client_data_classic(m);
    client_data_high_bytes(m);
}

void Encoder::client_data_classic(const svc::ClientData& m) {
    const uint32_t b = m.bits;
    if (b & SU_VIEWHEIGHT) w_.i8(m.view_height, "view height");
    if (b & SU_IDEALPITCH) w_.i8(m.ideal_pitch, "ideal pitch");
    for (int i = 0; i < 3; ++i) {
        if (b & (SU_PUNCH1 << i)) w_.i8(m.punch_angle[i], "punch angle");
        if (b & (SU_VELOCITY1 << i)) w_.i8(m.velocity[i] / 16, "velocity / 16");
    }
    w_.i32(m.items, "items");
    if (b & SU_WEAPONFRAME) w_.u8(m.weapon_frame & 0xff, "weapon frame");
    if (b & SU_ARMOR) w_.u8(m.armor & 0xff, "armor");
    if (b & SU_WEAPON) w_.u8(m.weapon & 0xff, "weapon");
    w_.i16(m.health, "health");
    for (int v : {m.ammo, m.shells, m.nails, m.rockets, m.cells}) w_.u8(v & 0xff, "ammo");
    w_.u8(m.active_weapon, "active weapon");
}

void Encoder::client_data_high_bytes(const svc::ClientData& m) {
    const std::pair<uint32_t, int> high_bytes[] = {
        {SU_WEAPON2, m.weapon}, {SU_ARMOR2, m.armor},
        {SU_AMMO2, m.ammo},     {SU_SHELLS2, m.shells},
        {SU_NAILS2, m.nails},   {SU_ROCKETS2, m.rockets},
        {SU_CELLS2, m.cells},   {SU_WEAPONFRAME2, m.weapon_frame}};
    for (const auto& [bit, value] : high_bytes) {
        if (m.bits & bit) w_.u8(value >> 8, "high byte");
    }
    if (m.bits & SU_WEAPONALPHA) w_.u8(m.weapon_alpha, "weapon alpha");
}

void Encoder::encode_message(const svc::Particle& m) {
    svc(m.kSvc);
    coords(m.origin);
    for (float d : m.direction) {
        w_.i8(quantize(d, 16.0, -128, 127, "particle direction"), "particle direction");
    }
    w_.u8(m.count, "particle count");
    w_.u8(m.color, "particle color");
}

void Encoder::entity_state(const EntityState& s, int flags) {
    require_default((flags & B_ALPHA) != 0, s.alpha, 0, "baseline alpha");
    if (flags & B_LARGEMODEL) {
        w_.u16(s.model, "baseline model");
    } else {
        w_.u8(s.model, "baseline model (without B_LARGEMODEL)");
    }
    if (flags & B_LARGEFRAME) {
        w_.u16(s.frame, "baseline frame");
    } else {
        w_.u8(s.frame, "baseline frame (without B_LARGEFRAME)");
    }
    w_.u8(s.colormap, "colormap");
    w_.u8(s.skin, "skin");
    for (int i = 0; i < 3; ++i) {
        coord(s.origin[i]);
        angle(s.angles[i]);
    }
    if (flags & B_ALPHA) w_.u8(s.alpha, "baseline alpha");
}

void Encoder::static_sound(const StaticSoundFields& s, bool large_index) {
    coords(s.origin);
    if (large_index) {
        w_.u16(s.sound, "sound index");
    } else {
        w_.u8(s.sound, "sound index");
    }
    w_.u8(s.volume, "volume");
    w_.u8(quantize(s.attenuation, 64.0, 0, 255, "attenuation"), "attenuation");
}

void Encoder::encode_message(const svc::TempEntity& m) {
    if (m.type < 0 || m.type >= kTempEntityKinds) {
        fail("unknown temp entity type " + std::to_string(m.type));
    }
    const bool beam = is_beam(m.type);
    const bool explosion2 = m.type == TE_EXPLOSION2;
    require_default(beam, m.entity, 0, "temp entity owner");
    require_default(beam, m.end, Vec3{}, "temp entity end point");
    require_default(explosion2, m.color_start, 0, "temp entity colour start");
    require_default(explosion2, m.color_length, 0, "temp entity colour length");
    svc(m.kSvc);
    w_.u8(m.type, "temp entity type");
    if (beam) w_.i16(m.entity, "beam entity");
    coords(m.origin);
    if (beam) coords(m.end);
    if (explosion2) {
        w_.u8(m.color_start, "colour start");
        w_.u8(m.color_length, "colour length");
    }
}

void Encoder::encode_message(const svc::Fog& m) {
    require_fitz("svc_fog");
    svc(m.kSvc);
    w_.u8(quantize(m.density, 255.0, 0, 255, "fog density"), "fog density");
    for (float c : m.color) w_.u8(quantize(c, 255.0, 0, 255, "fog colour"), "fog colour");
    w_.i16(quantize(m.fade_time, 100.0, -32768, 32767, "fog time"), "fog time");
}

uint32_t Encoder::entity_update_bits(const svc::EntityUpdate& m) const {
    const uint32_t bits = m.bits | U_SIGNAL;
    if ((bits & 0xff00) && !(bits & U_MOREBITS)) fail("update bits 8..15 need U_MOREBITS");
    if (!fitz() && bits > 0x7fff) fail("update bits above 14 need protocol 666 or 999");
    if ((bits & 0xff0000) && !(bits & U_EXTEND1)) fail("update bits 16..23 need U_EXTEND1");
    if ((bits & 0xff000000) && !(bits & U_EXTEND2)) fail("update bits 24..31 need U_EXTEND2");
    return bits;
}

void Encoder::encode_message(const svc::EntityUpdate& m) {
    const uint32_t bits = entity_update_bits(m);
    auto has = [bits](uint32_t bit) { return (bits & bit) != 0; };
    require_split(has(U_MODEL), has(U_MODEL2), m.model, "model");
    require_split(has(U_FRAME), has(U_FRAME2), m.frame, "frame");
    require_default(has(U_COLORMAP), m.colormap, 0, "colormap");
    require_default(has(U_SKIN), m.skin, 0, "skin");
    require_default(has(U_EFFECTS), m.effects, 0, "effects");
    const uint32_t origin_bits[3] = {U_ORIGIN1, U_ORIGIN2, U_ORIGIN3};
    const uint32_t angle_bits[3] = {U_ANGLE1, U_ANGLE2, U_ANGLE3};
    for (int i = 0; i < 3; ++i) {
        require_default(has(origin_bits[i]), m.origin[i], 0.0f, "origin");
        require_default(has(angle_bits[i]), m.angles[i], 0.0f, "angle");
    }
    require_default(has(U_ALPHA), m.alpha, 0, "alpha");
    require_default(has(U_SCALE), m.scale, 0, "scale");
    require_default(has(U_LERPFINISH), m.lerp_finish, 0.0f, "lerp finish");
    w_.u8(bits & 0xff, "update bits");
    if (has(U_MOREBITS)) w_.u8((bits >> 8) & 0xff, "update bits");
    if (has(U_EXTEND1)) w_.u8((bits >> 16) & 0xff, "update bits");
    if (has(U_EXTEND2)) w_.u8((bits >> 24) & 0xff, "update bits");
    if (has(U_LONGENTITY)) {
        require_non_negative(m.entity);
        w_.i16(m.entity, "entity");
    } else {
        w_.u8(m.entity, "entity (without U_LONGENTITY)");
    }
    entity_update_fields(m);
    if (fitz()) entity_update_fitz_fields(m);
}

void Encoder::entity_update_fields(const svc::EntityUpdate& m) {
    if (m.has(U_MODEL)) w_.u8(m.model & 0xff, "model");
    if (m.has(U_FRAME)) w_.u8(m.frame & 0xff, "frame");
    if (m.has(U_COLORMAP)) w_.u8(m.colormap, "colormap");
    if (m.has(U_SKIN)) w_.u8(m.skin, "skin");
    if (m.has(U_EFFECTS)) w_.u8(m.effects, "effects");
    const uint32_t origin_bits[3] = {U_ORIGIN1, U_ORIGIN2, U_ORIGIN3};
    const uint32_t angle_bits[3] = {U_ANGLE1, U_ANGLE2, U_ANGLE3};
    for (int i = 0; i < 3; ++i) {
        if (m.has(origin_bits[i])) coord(m.origin[i]);
        if (m.has(angle_bits[i])) angle(m.angles[i]);
    }
}

void Encoder::entity_update_fitz_fields(const svc::EntityUpdate& m) {
    if (m.has(U_ALPHA)) w_.u8(m.alpha, "alpha");
    if (m.has(U_SCALE)) w_.u8(m.scale, "scale");
    if (m.has(U_FRAME2)) w_.u8(m.frame >> 8, "frame high byte");
    if (m.has(U_MODEL2)) w_.u8(m.model >> 8, "model high byte");
    if (m.has(U_LERPFINISH)) {
        w_.u8(quantize(m.lerp_finish, 255.0, 0, 255, "lerp finish"), "lerp finish");
    }
}

}  // namespace

Result<std::vector<uint8_t>> encode_server_messages(std::span<const ServerMessage> messages,
                                                    protocol::ProtocolState& state) {
    std::vector<uint8_t> out;
    Encoder encoder(out, state);
    for (size_t i = 0; i < messages.size(); ++i) {
        size_t start = out.size();
        try {
            encoder.encode(messages[i]);
        } catch (const FormatError& e) {
            std::string kind(message_kind_name(message_kind(messages[i])));
            return Error{kEncoderFile, start,
                         "message " + std::to_string(i) + " (" + kind + "): " + e.error().message};
        }
    }
    return out;
}

}  // namespace nq

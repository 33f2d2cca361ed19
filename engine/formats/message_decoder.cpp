#include "formats/message_decoder.h"

#include <cmath>

#include "common/byte_reader.h"

namespace nq {
namespace {

using namespace protocol;

// Reads the fields of one message at a time; the protocol state decides how coordinates and
// angles are encoded. Every read is bounds-checked by ByteReader (it throws FormatError).
class Decoder {
  public:
    Decoder(ByteReader& r, ProtocolState& state, std::vector<std::string>& warnings)
        : r_(r), state_(state), warnings_(warnings) {}

    // `cmd` is the message's first byte, already consumed.
    ServerMessage decode(int cmd, size_t start);

  private:
    uint32_t rmq_flags() const { return state_.protocol == kRmq ? state_.flags : 0; }
    bool fitz() const { return has_fitz_extensions(state_.protocol); }

    float finite_float(const char* what);
    float coord();
    float angle();
    Vec3 coords();
    Vec3 angles();
    int entity_number();

    ServerMessage decode_fixed(int cmd, size_t start);
    ServerMessage decode_fitz(int cmd, size_t start);
    svc::Version version();
    svc::Sound sound();
    svc::ServerInfo server_info();
    std::vector<std::string> precache_list();
    svc::ClientData client_data();
    void client_data_high_bytes(svc::ClientData& c);
    svc::StopSound stop_sound();
    svc::Particle particle();
    svc::Damage damage();
    EntityState entity_state(int flags);
    StaticSoundFields static_sound(bool large_index);
    svc::TempEntity temp_entity();
    svc::Fog fog();
    svc::EntityUpdate entity_update(int first_byte);
    void entity_update_fields(svc::EntityUpdate& u);
    void entity_update_fitz_fields(svc::EntityUpdate& u);

    ByteReader& r_;
    ProtocolState& state_;
    std::vector<std::string>& warnings_;
};

float Decoder::finite_float(const char* what) {
    size_t at = r_.tell();
    float f = r_.f32();
    if (!std::isfinite(f)) r_.fail_at(at, std::string(what) + " is NaN or infinite");
    return f;
}

// Coordinate encodings: see PRFL_* in protocol.h (the arithmetic matches the engines': double,
// then rounded to float).
float Decoder::coord() {
    uint32_t flags = rmq_flags();
    if (flags & PRFL_FLOATCOORD) return finite_float("coordinate");
    if (flags & PRFL_INT32COORD) return static_cast<float>(r_.i32() / 16.0);
    if (flags & PRFL_24BITCOORD) {
        int whole = r_.i16();
        int fraction = r_.u8();
        return static_cast<float>(whole + fraction / 255.0);
    }
    return static_cast<float>(r_.i16() / 8.0);
}

float Decoder::angle() {
    uint32_t flags = rmq_flags();
    if (flags & PRFL_FLOATANGLE) return finite_float("angle");
    if (flags & PRFL_SHORTANGLE) return static_cast<float>(r_.i16() * (360.0 / 65536));
    return static_cast<float>(r_.i8() * (360.0 / 256));
}

Vec3 Decoder::coords() {
    Vec3 v;
    for (float& c : v) c = coord();
    return v;
}

Vec3 Decoder::angles() {
    Vec3 v;
    for (float& a : v) a = angle();
    return v;
}

// An int16 entity number; engines reject negative ones.
int Decoder::entity_number() {
    size_t at = r_.tell();
    int e = r_.i16();
    if (e < 0) r_.fail_at(at, "negative entity number " + std::to_string(e));
    return e;
}

ServerMessage Decoder::decode(int cmd, size_t start) {
    if (cmd & U_SIGNAL) return entity_update(cmd);
    if (cmd >= svc_skybox) return decode_fitz(cmd, start);
    return decode_fixed(cmd, start);
}

ServerMessage Decoder::decode_fixed(int cmd, size_t start) {
    switch (cmd) {
        case svc_bad:
            r_.fail_at(start, "svc_bad is an illegible message");
        case svc_nop:
            return svc::Nop{};
        case svc_disconnect:
            return svc::Disconnect{};
        case svc_updatestat: {
            int stat = r_.u8();
            return svc::UpdateStat{stat, r_.i32()};
        }
        case svc_version:
            return version();
        case svc_setview:
            return svc::SetView{r_.i16()};
        case svc_sound:
            return sound();
        case svc_time:
            return svc::Time{finite_float("time")};
        case svc_print:
            return svc::Print{r_.c_string()};
        case svc_stufftext:
            return svc::StuffText{r_.c_string()};
        case svc_setangle:
            return svc::SetAngle{angles()};
        case svc_serverinfo:
            return server_info();
        case svc_lightstyle: {
            int style = r_.u8();
            return svc::LightStyle{style, r_.c_string()};
        }
        case svc_updatename: {
            int client = r_.u8();
            return svc::UpdateName{client, r_.c_string()};
        }
        case svc_updatefrags: {
            int client = r_.u8();
            return svc::UpdateFrags{client, r_.i16()};
        }
        case svc_clientdata:
            return client_data();
        case svc_stopsound:
            return stop_sound();
        case svc_updatecolors: {
            int client = r_.u8();
            return svc::UpdateColors{client, r_.u8()};
        }
        case svc_particle:
            return particle();
        case svc_damage:
            return damage();
        case svc_spawnstatic:
            return svc::SpawnStatic{entity_state(0)};
        case svc_spawnbinary:
            r_.fail_at(start, "svc_spawnbinary is obsolete and has no defined layout");
        case svc_spawnbaseline: {
            int entity = entity_number();
            return svc::SpawnBaseline{entity, entity_state(0)};
        }
        case svc_temp_entity:
            return temp_entity();
        case svc_setpause:
            return svc::SetPause{r_.u8()};
        case svc_signonnum:
            return svc::SignonNum{r_.u8()};
        case svc_centerprint:
            return svc::CenterPrint{r_.c_string()};
        case svc_killedmonster:
            return svc::KilledMonster{};
        case svc_foundsecret:
            return svc::FoundSecret{};
        case svc_spawnstaticsound:
            return svc::SpawnStaticSound{static_sound(false)};
        case svc_intermission:
            return svc::Intermission{};
        case svc_finale:
            return svc::Finale{r_.c_string()};
        case svc_cdtrack: {
            int track = r_.u8();
            return svc::CdTrack{track, r_.u8()};
        }
        case svc_sellscreen:
            return svc::SellScreen{};
        case svc_cutscene:
            return svc::Cutscene{r_.c_string()};
        default:
            r_.fail_at(start, "unknown server message number " + std::to_string(cmd));
    }
}

// FitzQuake's additions; like FitzQuake-family clients, accepted under any protocol.
ServerMessage Decoder::decode_fitz(int cmd, size_t start) {
    switch (cmd) {
        case svc_skybox:
            return svc::Skybox{r_.c_string()};
        case svc_bf:
            return svc::Bf{};
        case svc_fog:
            return fog();
        case svc_spawnbaseline2: {
            int entity = entity_number();
            int flags = r_.u8();
            return svc::SpawnBaseline2{entity, flags, entity_state(flags)};
        }
        case svc_spawnstatic2: {
            int flags = r_.u8();
            return svc::SpawnStatic2{flags, entity_state(flags)};
        }
        case svc_spawnstaticsound2:
            return svc::SpawnStaticSound2{static_sound(true)};
        default:
            r_.fail_at(start, "unknown server message number " + std::to_string(cmd));
    }
}

svc::Version Decoder::version() {
    size_t at = r_.tell();
    int32_t p = r_.i32();
    if (!is_supported(p)) {
        r_.fail_at(at, "unsupported protocol " + std::to_string(p) + " (expected 15, 666 or 999)");
    }
    state_.protocol = p;
    if (p != kRmq) state_.flags = 0;
    return svc::Version{p};
}

svc::Sound Decoder::sound() {
    svc::Sound s;
    s.field_mask = r_.u8();
    if (s.field_mask & SND_VOLUME) s.volume = r_.u8();
    if (s.field_mask & SND_ATTENUATION) s.attenuation = r_.u8() / 64.0f;
    if (s.field_mask & SND_LARGEENTITY) {
        s.entity = r_.u16();
        s.channel = r_.u8();
    } else {
        int packed = r_.u16();  // entity << 3 | channel
        s.entity = packed >> 3;
        s.channel = packed & 7;
    }
    s.sound = (s.field_mask & SND_LARGESOUND) ? r_.u16() : r_.u8();
    s.origin = coords();
    return s;
}

svc::ServerInfo Decoder::server_info() {
    svc::ServerInfo si;
    size_t at = r_.tell();
    si.protocol = r_.i32();
    if (!is_supported(si.protocol)) {
        r_.fail_at(at, "unsupported protocol " + std::to_string(si.protocol) +
                           " (expected 15, 666 or 999)");
    }
    if (si.protocol == kRmq) {
        si.protocol_flags = r_.u32();
        if (si.protocol_flags & ~kKnownProtocolFlags) {
            warnings_.push_back("protocol 999 flags " + std::to_string(si.protocol_flags) +
                                " include unknown bits");
        }
    }
    si.max_clients = r_.u8();
    if (si.max_clients < 1 || si.max_clients > 16) {
        warnings_.push_back("serverinfo max_clients " + std::to_string(si.max_clients) +
                            " is outside 1..16");
    }
    si.game_type = r_.u8();
    si.level_name = r_.c_string();
    si.models = precache_list();
    si.sounds = precache_list();
    if (si.models.empty()) warnings_.push_back("serverinfo lists no world model");
    state_ = ProtocolState{si.protocol, si.protocol_flags};
    return si;
}

// Strings up to an empty one. Bounded by the buffer: each needs at least its NUL byte.
std::vector<std::string> Decoder::precache_list() {
    std::vector<std::string> names;
    for (std::string name = r_.c_string(); !name.empty(); name = r_.c_string()) {
        names.push_back(std::move(name));
    }
    return names;
}

svc::ClientData Decoder::client_data() {
    svc::ClientData c;
    c.bits = r_.u16();
    // FitzQuake-family clients read the extension bytes whatever the protocol.
    if (c.bits & SU_EXTEND1) c.bits |= static_cast<uint32_t>(r_.u8()) << 16;
    if (c.bits & SU_EXTEND2) c.bits |= static_cast<uint32_t>(r_.u8()) << 24;
    if (c.bits & SU_VIEWHEIGHT) c.view_height = r_.i8();
    if (c.bits & SU_IDEALPITCH) c.ideal_pitch = r_.i8();
    for (int i = 0; i < 3; ++i) {  // punch and velocity interleave per axis
        if (c.bits & (SU_PUNCH1 << i)) c.punch_angle[i] = r_.i8();
        if (c.bits & (SU_VELOCITY1 << i)) c.velocity[i] = r_.i8() * 16;
    }
    c.items = r_.i32();  // always sent (servers always set SU_ITEMS)
    if (c.bits & SU_WEAPONFRAME) c.weapon_frame = r_.u8();
    if (c.bits & SU_ARMOR) c.armor = r_.u8();
    if (c.bits & SU_WEAPON) c.weapon = r_.u8();
    c.health = r_.i16();
    c.ammo = r_.u8();
    c.shells = r_.u8();
    c.nails = r_.u8();
    c.rockets = r_.u8();
    c.cells = r_.u8();
    c.active_weapon = r_.u8();
    client_data_high_bytes(c);
    return c;
}

// FitzQuake: high bytes of values that can exceed 255, after all the classic fields.
void Decoder::client_data_high_bytes(svc::ClientData& c) {
    const std::pair<uint32_t, int*> high_bytes[] = {
        {SU_WEAPON2, &c.weapon}, {SU_ARMOR2, &c.armor},
        {SU_AMMO2, &c.ammo},     {SU_SHELLS2, &c.shells},
        {SU_NAILS2, &c.nails},   {SU_ROCKETS2, &c.rockets},
        {SU_CELLS2, &c.cells},   {SU_WEAPONFRAME2, &c.weapon_frame}};
    for (const auto& [bit, value] : high_bytes) {
        if (c.bits & bit) *value |= r_.u8() << 8;
    }
    if (c.bits & SU_WEAPONALPHA) c.weapon_alpha = r_.u8();
}

svc::StopSound Decoder::stop_sound() {
    int packed = r_.u16();
    return svc::StopSound{packed >> 3, packed & 7};
}

svc::Particle Decoder::particle() {
    svc::Particle p;
    p.origin = coords();
    for (float& d : p.direction) d = static_cast<float>(r_.i8() / 16.0);
    p.count = r_.u8();
    p.color = r_.u8();
    return p;
}

svc::Damage Decoder::damage() {
    svc::Damage d;
    d.armor = r_.u8();
    d.blood = r_.u8();
    d.from = coords();
    return d;
}

// Baseline layout; `flags` (B_*) is 0 for the version-1 messages.
EntityState Decoder::entity_state(int flags) {
    EntityState s;
    s.model = (flags & B_LARGEMODEL) ? r_.u16() : r_.u8();
    s.frame = (flags & B_LARGEFRAME) ? r_.u16() : r_.u8();
    s.colormap = r_.u8();
    s.skin = r_.u8();
    for (int i = 0; i < 3; ++i) {  // origin and angle interleave per axis
        s.origin[i] = coord();
        s.angles[i] = angle();
    }
    if (flags & B_ALPHA) s.alpha = r_.u8();
    return s;
}

StaticSoundFields Decoder::static_sound(bool large_index) {
    StaticSoundFields s;
    s.origin = coords();
    s.sound = large_index ? r_.u16() : r_.u8();
    s.volume = r_.u8();
    s.attenuation = r_.u8() / 64.0f;
    return s;
}

svc::TempEntity Decoder::temp_entity() {
    svc::TempEntity t;
    size_t at = r_.tell();
    t.type = r_.u8();
    if (t.type >= kTempEntityKinds) {
        r_.fail_at(at, "unknown temp entity type " + std::to_string(t.type));
    }
    if (is_beam(t.type)) t.entity = r_.i16();
    t.origin = coords();
    if (is_beam(t.type)) t.end = coords();
    if (t.type == TE_EXPLOSION2) {
        t.color_start = r_.u8();
        t.color_length = r_.u8();
    }
    return t;
}

svc::Fog Decoder::fog() {
    svc::Fog f;
    f.density = static_cast<float>(r_.u8() / 255.0);
    for (float& c : f.color) c = static_cast<float>(r_.u8() / 255.0);
    f.fade_time = static_cast<float>(r_.i16() / 100.0);
    return f;
}

svc::EntityUpdate Decoder::entity_update(int first_byte) {
    svc::EntityUpdate u;
    u.bits = static_cast<uint32_t>(first_byte);
    if (u.bits & U_MOREBITS) u.bits |= static_cast<uint32_t>(r_.u8()) << 8;
    if (fitz()) {
        if (u.bits & U_EXTEND1) u.bits |= static_cast<uint32_t>(r_.u8()) << 16;
        if (u.bits & U_EXTEND2) u.bits |= static_cast<uint32_t>(r_.u8()) << 24;
    } else if (u.bits & U_TRANS) {
        // Nehahra reused this bit in protocol 15 for extra float fields we do not decode.
        r_.fail("update bit 15 (Nehahra's U_TRANS) is not part of protocol 15");
    }
    u.entity = (u.bits & U_LONGENTITY) ? entity_number() : r_.u8();
    entity_update_fields(u);
    if (fitz()) entity_update_fitz_fields(u);
    return u;
}

void Decoder::entity_update_fields(svc::EntityUpdate& u) {
    if (u.has(U_MODEL)) u.model = r_.u8();
    if (u.has(U_FRAME)) u.frame = r_.u8();
    if (u.has(U_COLORMAP)) u.colormap = r_.u8();
    if (u.has(U_SKIN)) u.skin = r_.u8();
    if (u.has(U_EFFECTS)) u.effects = r_.u8();
    const uint32_t origin_bits[3] = {U_ORIGIN1, U_ORIGIN2, U_ORIGIN3};
    const uint32_t angle_bits[3] = {U_ANGLE1, U_ANGLE2, U_ANGLE3};
    for (int i = 0; i < 3; ++i) {  // origin and angle interleave per axis
        if (u.has(origin_bits[i])) u.origin[i] = coord();
        if (u.has(angle_bits[i])) u.angles[i] = angle();
    }
}

void Decoder::entity_update_fitz_fields(svc::EntityUpdate& u) {
    if (u.has(U_ALPHA)) u.alpha = r_.u8();
    if (u.has(U_SCALE)) u.scale = r_.u8();
    if (u.has(U_FRAME2)) u.frame |= r_.u8() << 8;
    if (u.has(U_MODEL2)) u.model |= r_.u8() << 8;
    if (u.has(U_LERPFINISH)) u.lerp_finish = static_cast<float>(r_.u8() / 255.0);
}

std::string message_label(int cmd) {
    if (cmd & U_SIGNAL) return std::string(message_kind_name(kEntityUpdateKind));
    std::string_view name = svc_name(cmd);
    if (name == "svc_unknown") return "svc " + std::to_string(cmd);
    return std::string(name);
}

// Re-throws a field error with the block and the message being decoded in front.
[[noreturn]] void rethrow_in_context(const FormatError& e, size_t block_index, int cmd,
                                     size_t start, int previous_cmd) {
    std::string previous = previous_cmd < 0 ? "none" : message_label(previous_cmd);
    Error err = e.error();
    err.message = "block " + std::to_string(block_index) + ": " + message_label(cmd) +
                  " at message byte " + std::to_string(start) + " (previous: " + previous +
                  "): " + err.message;
    throw FormatError(std::move(err));
}

// Decodes every message left in `r` into `block` (appending), with errors in context.
void decode_messages(ByteReader& r, size_t block_index, protocol::ProtocolState& state,
                     DecodedBlock& block) {
    Decoder decoder(r, state, block.warnings);
    int previous_cmd = -1;  // for error messages only
    while (!r.at_end()) {
        size_t start = r.tell();
        int cmd = r.u8();
        try {
            ServerMessage message = decoder.decode(cmd, start);
            block.messages.push_back({start, r.tell() - start, std::move(message)});
        } catch (const FormatError& e) {
            rethrow_in_context(e, block_index, cmd, start, previous_cmd);
        }
        previous_cmd = cmd;
    }
}

}  // namespace

Result<DecodedBlock> decode_server_message(std::span<const uint8_t> buffer,
                                           const MessageSource& source,
                                           protocol::ProtocolState& state) {
    return capture_errors(source.file, [&]() -> DecodedBlock {
        ByteReader r(buffer, source.file, source.file_offset);
        DecodedBlock block;
        decode_messages(r, source.block_index, state, block);
        return block;
    });
}

ServerMessageDecoder::ServerMessageDecoder(std::string file) : reader_({}, std::move(file)) {}

std::optional<Error> ServerMessageDecoder::decode(std::span<const uint8_t> buffer,
                                                  size_t block_index, uint64_t file_offset,
                                                  protocol::ProtocolState& state) {
    block_.messages.clear();  // keeps the capacity
    block_.warnings.clear();
    reader_.restart(buffer, file_offset);
    auto decoded = capture_errors(reader_.file(), [&] {
        decode_messages(reader_, block_index, state, block_);
        return true;
    });
    if (!decoded) return decoded.error();
    return std::nullopt;
}

}  // namespace nq

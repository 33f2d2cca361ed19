#include "support/synth_dem.h"

#include <stdexcept>

#include "formats/dem.h"
#include "formats/message_encoder.h"

namespace nq::test {
namespace {

using namespace protocol;

// k * 360 / steps, the documented angle steps of the byte and short encodings.
float angle_step(int k, int steps) {
    return static_cast<float>(k * (360.0 / steps));
}

// whole + k/255, the documented 24-bit coordinate (as the engines compute it).
float coord24(int whole, int k) {
    return static_cast<float>(whole + k / 255.0);
}

uint32_t effective_flags(const ProtocolState& s) {
    return s.protocol == kRmq ? s.flags : 0;
}

// Hands out grid values in turn, so every field gets a different but representable value.
class Values {
  public:
    explicit Values(const ProtocolState& state)
        : coords_(grid_coords(state)), angles_(grid_angles(state)) {}

    float coord() { return coords_[next_coord_++ % coords_.size()]; }
    float angle() { return angles_[next_angle_++ % angles_.size()]; }
    Vec3 coords() { return {coord(), coord(), coord()}; }
    Vec3 angles() { return {angle(), angle(), angle()}; }

  private:
    std::vector<float> coords_;
    std::vector<float> angles_;
    size_t next_coord_ = 0;
    size_t next_angle_ = 0;
};

svc::ServerInfo server_info(const ProtocolState& s) {
    svc::ServerInfo si;
    si.protocol = s.protocol;
    si.protocol_flags = effective_flags(s);
    si.max_clients = 8;
    si.game_type = 1;
    si.level_name = "Synthetic Level";
    si.models = {"maps/synth.bsp", "*1", "progs/player.mdl", "progs/s_explod.spr"};
    si.sounds = {"weapons/r_exp3.wav", "misc/null.wav"};
    return si;
}

void add_simple_messages(std::vector<ServerMessage>& out, Values& v) {
    out.push_back(svc::Nop{});
    out.push_back(svc::Time{1.5f});
    out.push_back(svc::Print{"hello\nworld\n"});
    out.push_back(svc::StuffText{"bf\n"});
    out.push_back(svc::SetView{1});
    out.push_back(svc::SetAngle{v.angles()});
    out.push_back(svc::LightStyle{63, "abcz"});
    out.push_back(svc::UpdateName{7, "player"});
    out.push_back(svc::UpdateFrags{3, -5});
    out.push_back(svc::UpdateColors{2, 0x4f});
    out.push_back(svc::UpdateStat{13, -123456});
    out.push_back(svc::StopSound{8191, 7});
    out.push_back(svc::Particle{v.coords(), {-8.0f, 0.0f, 127 / 16.0f}, 255, 73});
    out.push_back(svc::Damage{3, 10, v.coords()});
    out.push_back(svc::SetPause{1});
    out.push_back(svc::SignonNum{2});
    out.push_back(svc::CenterPrint{"centre"});
    out.push_back(svc::KilledMonster{});
    out.push_back(svc::FoundSecret{});
    out.push_back(svc::Intermission{});
    out.push_back(svc::Finale{"The end"});
    out.push_back(svc::CdTrack{2, 3});
    out.push_back(svc::SellScreen{});
    out.push_back(svc::Cutscene{"cut"});
    out.push_back(svc::Disconnect{});
}

EntityState entity_state(Values& v, int model, int frame, int alpha) {
    EntityState s;
    s.model = model;
    s.frame = frame;
    s.colormap = 1;
    s.skin = 2;
    for (int i = 0; i < 3; ++i) {
        s.origin[i] = v.coord();
        s.angles[i] = v.angle();
    }
    s.alpha = alpha;
    return s;
}

void add_classic_entities(std::vector<ServerMessage>& out, Values& v) {
    out.push_back(svc::SpawnStatic{entity_state(v, 3, 7, 0)});
    out.push_back(svc::SpawnBaseline{300, entity_state(v, 255, 255, 0)});
    out.push_back(svc::SpawnStaticSound{{v.coords(), 255, 127, 3.0f}});
    for (int type = 0; type < kTempEntityKinds; ++type) {
        svc::TempEntity t;
        t.type = type;
        t.origin = v.coords();
        if (is_beam(type)) {
            t.entity = 1 + type;
            t.end = v.coords();
        }
        if (type == TE_EXPLOSION2) {
            t.color_start = 208;
            t.color_length = 8;
        }
        out.push_back(t);
    }
}

void add_sounds(std::vector<ServerMessage>& out, Values& v, bool fitz) {
    svc::Sound plain;  // defaults only: no optional field
    plain.entity = 8191;
    plain.channel = 7;
    plain.sound = 255;
    plain.origin = v.coords();
    out.push_back(plain);

    svc::Sound full = plain;
    full.field_mask = SND_VOLUME | SND_ATTENUATION | SND_LOOPING;
    full.volume = 0;
    full.attenuation = 255 / 64.0f;
    full.origin = v.coords();
    out.push_back(full);
    if (!fitz) return;

    svc::Sound large = full;
    large.field_mask |= SND_LARGEENTITY | SND_LARGESOUND;
    large.entity = 65535;
    large.channel = 255;
    large.sound = 65535;
    large.origin = v.coords();
    out.push_back(large);
}

svc::ClientData client_data(uint32_t bits, bool fitz) {
    svc::ClientData c;
    c.bits = bits;
    if (bits & SU_VIEWHEIGHT) c.view_height = -128;
    if (bits & SU_IDEALPITCH) c.ideal_pitch = 127;
    for (int i = 0; i < 3; ++i) {
        if (bits & (SU_PUNCH1 << i)) c.punch_angle[i] = -3 + 5 * i;
        if (bits & (SU_VELOCITY1 << i)) c.velocity[i] = 16 * (-128 + 127 * i);
    }
    c.items = static_cast<int32_t>(0x8000'1234u);
    c.health = -32768;
    c.active_weapon = 64;
    const int high = fitz ? 0x100 : 0;  // FitzQuake runs send high bytes for large values
    c.weapon_frame = (bits & SU_WEAPONFRAME ? 12 : 0) | (bits & SU_WEAPONFRAME2 ? 0x300 : 0);
    c.armor = (bits & SU_ARMOR ? 200 : 0) | (bits & SU_ARMOR2 ? 0x100 : 0);
    c.weapon = (bits & SU_WEAPON ? 3 : 0) | (bits & SU_WEAPON2 ? 0x200 : 0);
    c.ammo = 25 | (bits & SU_AMMO2 ? high : 0);
    c.shells = 26 | (bits & SU_SHELLS2 ? high * 2 : 0);
    c.nails = 27 | (bits & SU_NAILS2 ? high * 3 : 0);
    c.rockets = 28 | (bits & SU_ROCKETS2 ? high * 4 : 0);
    c.cells = 29 | (bits & SU_CELLS2 ? high * 5 : 0);
    if (bits & SU_WEAPONALPHA) c.weapon_alpha = 128;
    return c;
}

// An update whose fields are all set to representable values for `bits`.
svc::EntityUpdate entity_update(uint32_t bits, Values& v, bool fitz) {
    svc::EntityUpdate u;
    u.bits = bits | U_SIGNAL;
    u.entity = (bits & U_LONGENTITY) ? 32767 : 200;
    u.model = (bits & U_MODEL ? 0x12 : 0) | (bits & U_MODEL2 ? 0x0300 : 0);
    u.frame = (bits & U_FRAME ? 0xff : 0) | (bits & U_FRAME2 ? 0xff00 : 0);
    if (bits & U_COLORMAP) u.colormap = 4;
    if (bits & U_SKIN) u.skin = 5;
    if (bits & U_EFFECTS) u.effects = 8;
    const uint32_t origin_bits[3] = {U_ORIGIN1, U_ORIGIN2, U_ORIGIN3};
    const uint32_t angle_bits[3] = {U_ANGLE1, U_ANGLE2, U_ANGLE3};
    for (int i = 0; i < 3; ++i) {
        if (bits & origin_bits[i]) u.origin[i] = v.coord();
        if (bits & angle_bits[i]) u.angles[i] = v.angle();
    }
    if (fitz && (bits & U_ALPHA)) u.alpha = 1;
    if (fitz && (bits & U_SCALE)) u.scale = 16;
    if (fitz && (bits & U_LERPFINISH)) u.lerp_finish = static_cast<float>(25 / 255.0);
    return u;
}

void add_masked_messages(std::vector<ServerMessage>& out, Values& v, bool fitz) {
    const uint32_t classic_clientdata = 0x7fff;  // every bit below SU_EXTEND1
    out.push_back(client_data(SU_ITEMS, fitz));
    out.push_back(client_data(classic_clientdata, fitz));
    if (fitz) out.push_back(client_data(0xffff'ffffu, fitz));

    const uint32_t classic_update = 0x7fff;  // every bit below U_EXTEND1
    out.push_back(entity_update(0, v, fitz));
    out.push_back(entity_update(U_MOREBITS | U_ORIGIN2, v, fitz));  // byte entity, MOREBITS
    out.push_back(entity_update(classic_update, v, fitz));
    if (fitz) {
        out.push_back(entity_update(0xffff'ffffu, v, fitz));
        out.push_back(entity_update(U_MOREBITS | U_EXTEND1 | U_MODEL2 | U_FRAME2, v, fitz));
    }
}

void add_fitz_messages(std::vector<ServerMessage>& out, Values& v) {
    out.push_back(svc::Skybox{"sky1"});
    out.push_back(svc::Skybox{""});
    out.push_back(svc::Bf{});
    svc::Fog fog;
    fog.density = static_cast<float>(51 / 255.0);
    fog.color = {static_cast<float>(255 / 255.0), static_cast<float>(128 / 255.0), 0.0f};
    fog.fade_time = static_cast<float>(250 / 100.0);
    out.push_back(fog);
    const int all_flags = B_LARGEMODEL | B_LARGEFRAME | B_ALPHA;
    out.push_back(svc::SpawnBaseline2{32767, all_flags, entity_state(v, 700, 65535, 128)});
    out.push_back(svc::SpawnBaseline2{2, 0, entity_state(v, 9, 1, 0)});
    out.push_back(svc::SpawnStatic2{all_flags, entity_state(v, 65535, 300, 255)});
    out.push_back(svc::SpawnStatic2{B_ALPHA, entity_state(v, 4, 2, 1)});
    out.push_back(svc::SpawnStaticSound2{{v.coords(), 300, 255, 0.5f}});
}

// One demo: serverinfo block, then the full catalogue, then frames with svc_time.
std::vector<std::vector<ServerMessage>> demo_blocks(const ProtocolState& state) {
    std::vector<ServerMessage> all = every_message_kind(state);
    std::vector<std::vector<ServerMessage>> blocks;
    blocks.push_back({all.front()});
    blocks.push_back(std::vector<ServerMessage>(all.begin() + 1, all.end()));
    for (int frame = 0; frame < 3; ++frame) {
        blocks.push_back({svc::Time{2.0f + 0.1f * frame}, svc::Nop{}});
    }
    return blocks;
}

std::string state_name(const ProtocolState& s) {
    return "p" + std::to_string(s.protocol) + "_flags" + std::to_string(s.flags);
}

}  // namespace

std::vector<float> grid_coords(const ProtocolState& state) {
    uint32_t flags = effective_flags(state);
    if (flags & PRFL_FLOATCOORD) return {-98765.4296875f, 0.1f, 12345.678f, 3.0e6f};
    if (flags & PRFL_INT32COORD) return {-100000.0625f, 0.5f, 12.4375f, 3.0e6f + 0.25f};
    if (flags & PRFL_24BITCOORD) {
        return {coord24(-20000, 17), coord24(0, 0), coord24(12, 128), coord24(32767, 254),
                coord24(-32768, 0)};
    }
    return {-4096.0f, 0.0f, 12.5f, -0.125f, 4095.875f};
}

std::vector<float> grid_angles(const ProtocolState& state) {
    uint32_t flags = effective_flags(state);
    if (flags & PRFL_FLOATANGLE) return {-179.9f, 0.25f, 33.3f, 359.5f};
    if (flags & PRFL_SHORTANGLE) {
        return {angle_step(-32768, 65536), angle_step(-1, 65536), angle_step(0, 65536),
                angle_step(12345, 65536), angle_step(32767, 65536)};
    }
    return {angle_step(-128, 256), angle_step(-1, 256), angle_step(0, 256), angle_step(45, 256),
            angle_step(127, 256)};
}

std::vector<uint32_t> rmq_flag_combinations(bool with_scale) {
    const uint32_t bits[] = {PRFL_FLOATCOORD, PRFL_INT32COORD, PRFL_24BITCOORD, PRFL_FLOATANGLE,
                             PRFL_SHORTANGLE};
    std::vector<uint32_t> out;
    for (uint32_t subset = 0; subset < 32; ++subset) {
        uint32_t flags = 0;
        for (int i = 0; i < 5; ++i) {
            if (subset & (1u << i)) flags |= bits[i];
        }
        out.push_back(flags);
        if (with_scale) out.push_back(flags | PRFL_EDICTSCALE);
    }
    return out;
}

std::vector<ServerMessage> every_message_kind(const ProtocolState& state) {
    const bool fitz = has_fitz_extensions(state.protocol);
    Values v(state);
    std::vector<ServerMessage> out;
    out.push_back(server_info(state));
    out.push_back(svc::Version{state.protocol});
    add_simple_messages(out, v);
    add_classic_entities(out, v);
    add_sounds(out, v, fitz);
    add_masked_messages(out, v, fitz);
    if (fitz) add_fitz_messages(out, v);
    return out;
}

std::vector<uint8_t> build_demo(const std::vector<std::vector<ServerMessage>>& blocks,
                                ProtocolState initial, const std::string& cd_track_line) {
    Demo demo;
    demo.cd_track_line = cd_track_line;
    ProtocolState state = initial;
    for (size_t i = 0; i < blocks.size(); ++i) {
        auto bytes = encode_server_messages(blocks[i], state);
        if (!bytes) throw std::runtime_error("build_demo: " + bytes.error().to_string());
        DemoBlock block;
        float n = static_cast<float>(i);
        block.view_angles = {1.0f * n, 2.0f * n, 3.0f * n};
        block.message = std::move(bytes.value());
        demo.blocks.push_back(std::move(block));
    }
    return write_dem(demo);
}

std::vector<uint8_t> build_raw_demo(const std::vector<std::vector<uint8_t>>& messages,
                                    const std::string& cd_track_line) {
    Demo demo;
    demo.cd_track_line = cd_track_line;
    for (const auto& m : messages) {
        DemoBlock block;
        block.message = m;
        demo.blocks.push_back(block);
    }
    return write_dem(demo);
}

std::vector<SeedFile> synthetic_dem_seeds() {
    std::vector<ProtocolState> states = {{kNetQuake, 0}, {kFitzQuake, 0}};
    for (uint32_t flags : rmq_flag_combinations(true)) states.push_back({kRmq, flags});
    std::vector<SeedFile> seeds;
    for (const auto& s : states) {
        seeds.push_back({"synth_" + state_name(s) + ".dem", build_demo(demo_blocks(s))});
    }
    SeedFile cut{"synth_truncated_tail.dem", build_demo(demo_blocks({kFitzQuake, 0}))};
    cut.bytes.resize(cut.bytes.size() - 3);
    seeds.push_back(std::move(cut));
    return seeds;
}

}  // namespace nq::test

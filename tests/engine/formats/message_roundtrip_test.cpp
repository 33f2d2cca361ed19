// Server messages: encode -> decode round trips for protocol 15, 666 and every RMQ (999) flag
// combination; hand-written wire bytes checked against the documented encodings; the
// encoder's refusals.
#include <gtest/gtest.h>

#include <cstring>
#include <set>
#include <string>
#include <vector>

#include "formats/message_decoder.h"
#include "formats/message_encoder.h"
#include "support/synth_dem.h"

namespace nq {
namespace {

using namespace protocol;
using Bytes = std::vector<uint8_t>;

std::string describe(const ProtocolState& s) {
    return "protocol " + std::to_string(s.protocol) + " flags " + std::to_string(s.flags);
}

Bytes encode(const std::vector<ServerMessage>& messages, ProtocolState state) {
    auto bytes = encode_server_messages(messages, state);
    EXPECT_TRUE(bytes.ok()) << bytes.error().to_string();
    return bytes.ok() ? bytes.value() : Bytes{};
}

std::vector<ServerMessage> decode(const Bytes& bytes, ProtocolState& state) {
    auto block = decode_server_message(bytes, {"synth", 0, 0}, state);
    EXPECT_TRUE(block.ok()) << block.error().to_string();
    std::vector<ServerMessage> out;
    if (block.ok()) {
        for (const auto& m : block->messages) out.push_back(m.message);
    }
    return out;
}

// Encodes `messages` (which start with their own serverinfo) from a protocol-15 stream start,
// decodes them the same way, and expects the identical list and the same final state.
void expect_round_trip(const ProtocolState& state) {
    SCOPED_TRACE(describe(state));
    std::vector<ServerMessage> messages = test::every_message_kind(state);
    ProtocolState encoder_state, decoder_state;
    auto bytes = encode_server_messages(messages, encoder_state);
    ASSERT_TRUE(bytes.ok()) << bytes.error().to_string();
    auto block = decode_server_message(bytes.value(), {"synth", 0, 0}, decoder_state);
    ASSERT_TRUE(block.ok()) << block.error().to_string();
    EXPECT_TRUE(block->warnings.empty());
    ASSERT_EQ(block->messages.size(), messages.size());
    size_t offset = 0;
    for (size_t i = 0; i < messages.size(); ++i) {
        EXPECT_TRUE(block->messages[i].message == messages[i])
            << "message " << i << " (" << message_kind_name(message_kind(messages[i])) << ")";
        EXPECT_EQ(block->messages[i].offset, offset);  // messages tile the buffer
        offset += block->messages[i].size;
    }
    EXPECT_EQ(offset, bytes->size());
    EXPECT_EQ(decoder_state, encoder_state);
    EXPECT_EQ(decoder_state.protocol, state.protocol);
}

TEST(MessageRoundTrip, NetQuake15) {
    expect_round_trip({kNetQuake, 0});
}

TEST(MessageRoundTrip, FitzQuake666) {
    expect_round_trip({kFitzQuake, 0});
}

TEST(MessageRoundTrip, Rmq999EveryCoordinateAndAngleFlagCombination) {
    std::vector<uint32_t> combos = test::rmq_flag_combinations(true);
    ASSERT_EQ(combos.size(), 64u);
    for (uint32_t flags : combos) expect_round_trip({kRmq, flags});
}

// The test data itself must cover what the round trips claim (checked without the codec).
TEST(MessageRoundTrip, CatalogueCoversEveryKindAndEveryBit) {
    std::vector<ServerMessage> fitz = test::every_message_kind({kRmq, PRFL_FLOATCOORD});
    std::set<int> kinds;
    uint32_t update_bits = 0, clientdata_bits = 0;
    int sound_masks = 0, baseline_flags = 0;
    std::set<int> temp_entities;
    for (const auto& m : fitz) {
        kinds.insert(message_kind(m));
        if (auto* u = std::get_if<svc::EntityUpdate>(&m)) update_bits |= u->bits;
        if (auto* c = std::get_if<svc::ClientData>(&m)) clientdata_bits |= c->bits;
        if (auto* s = std::get_if<svc::Sound>(&m)) sound_masks |= s->field_mask;
        if (auto* b = std::get_if<svc::SpawnBaseline2>(&m)) baseline_flags |= b->flags;
        if (auto* t = std::get_if<svc::TempEntity>(&m)) temp_entities.insert(t->type);
    }
    for (int svc = 1; svc <= 44; ++svc) {
        bool assigned = svc_name(svc) != "svc_unknown" && svc != svc_spawnbinary;
        EXPECT_EQ(kinds.count(svc), assigned ? 1u : 0u) << svc_name(svc) << " " << svc;
    }
    EXPECT_EQ(kinds.count(kEntityUpdateKind), 1u);
    EXPECT_EQ(update_bits, 0xffffffffu);
    EXPECT_EQ(clientdata_bits, 0xffffffffu);
    EXPECT_EQ(sound_masks, 0x1f);
    EXPECT_EQ(baseline_flags, B_LARGEMODEL | B_LARGEFRAME | B_ALPHA);
    EXPECT_EQ(temp_entities.size(), static_cast<size_t>(kTempEntityKinds));

    uint32_t classic_update_bits = 0;
    for (const auto& m : test::every_message_kind({kNetQuake, 0})) {
        if (auto* u = std::get_if<svc::EntityUpdate>(&m)) classic_update_bits |= u->bits;
        EXPECT_LT(message_kind(m) < 128 ? message_kind(m) : 0, static_cast<int>(svc_skybox));
    }
    EXPECT_EQ(classic_update_bits, 0x7fffu);
}

// ---- wire bytes from the documented encodings, written by hand ------------------------------

Bytes float_bytes(float f) {
    uint32_t u;
    std::memcpy(&u, &f, sizeof u);
    return {static_cast<uint8_t>(u), static_cast<uint8_t>(u >> 8), static_cast<uint8_t>(u >> 16),
            static_cast<uint8_t>(u >> 24)};
}

// svc_damage carries exactly one coordinate triple after two bytes: a clean probe.
Bytes damage_bytes(float x, ProtocolState state) {
    return encode({svc::Damage{1, 2, {x, 0, 0}}}, state);
}

TEST(MessageWire, CoordinateEncodingsAndFlagPriority) {
    // 13.3 fixed point: 12.5 * 8 = 100.
    EXPECT_EQ(damage_bytes(12.5f, {kNetQuake, 0}), (Bytes{19, 1, 2, 100, 0, 0, 0, 0, 0}));
    // The same under 666, and under 999 without coordinate flags.
    EXPECT_EQ(damage_bytes(12.5f, {kFitzQuake, 0}).size(), 9u);
    EXPECT_EQ(damage_bytes(12.5f, {kRmq, PRFL_SHORTANGLE}).size(), 9u);
    // RMQ flags are ignored outside protocol 999.
    EXPECT_EQ(damage_bytes(12.5f, {kFitzQuake, PRFL_FLOATCOORD}).size(), 9u);
    // int32 / 16: 1.0 -> 16.
    Bytes i32 = damage_bytes(1.0f, {kRmq, PRFL_INT32COORD});
    EXPECT_EQ(Bytes(i32.begin() + 3, i32.begin() + 7), (Bytes{16, 0, 0, 0}));
    // 24-bit: -2 + 128/255 -> int16 -2, byte 128.
    Bytes c24 = damage_bytes(static_cast<float>(-2 + 128 / 255.0), {kRmq, PRFL_24BITCOORD});
    EXPECT_EQ(Bytes(c24.begin() + 3, c24.begin() + 6), (Bytes{0xfe, 0xff, 128}));
    // Float wins over int32 and 24-bit; int32 wins over 24-bit.
    Bytes f = damage_bytes(0.1f, {kRmq, PRFL_FLOATCOORD | PRFL_INT32COORD | PRFL_24BITCOORD});
    EXPECT_EQ(Bytes(f.begin() + 3, f.begin() + 7), float_bytes(0.1f));
    EXPECT_EQ(damage_bytes(1, {kRmq, PRFL_INT32COORD | PRFL_24BITCOORD}).size(), 3u + 12u);
}

TEST(MessageWire, AngleEncodingsAndFlagPriority) {
    auto setangle = [](float yaw, ProtocolState s) {
        return encode({svc::SetAngle{{0, yaw, 0}}}, s);
    };
    EXPECT_EQ(setangle(90, {kNetQuake, 0}), (Bytes{10, 0, 64, 0}));     // 90 * 256/360
    EXPECT_EQ(setangle(-90, {kNetQuake, 0}), (Bytes{10, 0, 0xc0, 0}));  // wraps to -64
    EXPECT_EQ(setangle(90, {kRmq, PRFL_SHORTANGLE}), (Bytes{10, 0, 0, 0x00, 0x40, 0, 0}));
    Bytes both = setangle(33.3f, {kRmq, PRFL_SHORTANGLE | PRFL_FLOATANGLE});
    ASSERT_EQ(both.size(), 13u);
    EXPECT_EQ(Bytes(both.begin() + 5, both.begin() + 9), float_bytes(33.3f));
    // Off-grid values round to the nearest step: 91 degrees -> 64.71 -> 65.
    EXPECT_EQ(setangle(91, {kNetQuake, 0})[2], 65);

    ProtocolState s{kNetQuake, 0};
    auto back = decode(Bytes{10, 0x80, 0x7f, 0x01}, s);
    ASSERT_EQ(back.size(), 1u);
    EXPECT_EQ(std::get<svc::SetAngle>(back[0]).angles, (Vec3{-180.0f, 178.59375f, 1.40625f}));
}

TEST(MessageWire, HandWrittenFitzMessagesDecode) {
    ProtocolState s{kFitzQuake, 0};
    // svc_sound: mask VOLUME|ATTENUATION|LARGEENTITY|LARGESOUND, vol 200, atten 128 (= 2.0),
    // entity 0x1234, channel 9, sound 0x0101, origin (8, -8, 0.125) in 13.3.
    Bytes sound = {6, 0x1b, 200, 128, 0x34, 0x12, 9, 0x01, 0x01, 64, 0, 0xc0, 0xff, 1, 0};
    // svc_clientdata: bits SU_ITEMS|SU_EXTEND1 + SU_WEAPON2 | SU_WEAPON, weapon 0x0203.
    Bytes clientdata = {15,   0x00, 0xc2, 0x01, 0x78, 0x56, 0x34, 0x12, 0x03,
                        0x64, 0x00, 1,    2,    3,    4,    5,    6,    0x02};
    // fast update: U_MOREBITS|U_ORIGIN1 + U_EXTEND1|U_LONGENTITY + U_ALPHA, entity 300,
    // origin x -1.0, alpha 1.
    Bytes update = {0x83, 0xc0, 0x01, 0x2c, 0x01, 0xf8, 0xff, 0x01};
    Bytes all = sound;
    all.insert(all.end(), clientdata.begin(), clientdata.end());
    all.insert(all.end(), update.begin(), update.end());
    auto messages = decode(all, s);
    ASSERT_EQ(messages.size(), 3u);

    const auto& snd = std::get<svc::Sound>(messages[0]);
    EXPECT_EQ(snd.volume, 200);
    EXPECT_EQ(snd.attenuation, 2.0f);
    EXPECT_EQ(snd.entity, 0x1234);
    EXPECT_EQ(snd.channel, 9);
    EXPECT_EQ(snd.sound, 0x0101);
    EXPECT_EQ(snd.origin, (Vec3{8.0f, -8.0f, 0.125f}));

    const auto& cd = std::get<svc::ClientData>(messages[1]);
    EXPECT_EQ(cd.bits, SU_ITEMS | SU_WEAPON | SU_EXTEND1 | SU_WEAPON2);
    EXPECT_EQ(cd.items, 0x12345678);
    EXPECT_EQ(cd.weapon, 0x0203);
    EXPECT_EQ(cd.health, 100);
    EXPECT_EQ(cd.ammo, 1);
    EXPECT_EQ(cd.cells, 5);
    EXPECT_EQ(cd.active_weapon, 6);
    EXPECT_EQ(cd.view_height, 22);  // default when SU_VIEWHEIGHT is clear

    const auto& u = std::get<svc::EntityUpdate>(messages[2]);
    EXPECT_EQ(u.bits, U_SIGNAL | U_MOREBITS | U_ORIGIN1 | U_EXTEND1 | U_LONGENTITY | U_ALPHA);
    EXPECT_EQ(u.entity, 300);
    EXPECT_EQ(u.origin[0], -1.0f);
    EXPECT_EQ(u.alpha, 1);

    // The same update under protocol 15 is Nehahra's U_TRANS hack: refused, not misread.
    ProtocolState nq15{kNetQuake, 0};
    EXPECT_FALSE(decode_server_message(update, {"x", 0, 0}, nq15).ok());
}

TEST(MessageWire, ServerInfoAndVersionSwitchTheDecoder) {
    ProtocolState s;
    svc::ServerInfo info;
    info.protocol = kRmq;
    info.protocol_flags = PRFL_FLOATCOORD | PRFL_EDICTSCALE | (1u << 12);  // one unknown bit
    info.models = {"maps/e1m1.bsp"};
    Bytes bytes = encode({info}, s);
    bytes.push_back(19);  // svc_damage, coordinates now floats
    bytes.insert(bytes.end(), {1, 2});
    for (int i = 0; i < 3; ++i) {
        Bytes f = float_bytes(0.5f * i);
        bytes.insert(bytes.end(), f.begin(), f.end());
    }
    ProtocolState state;
    auto block = decode_server_message(bytes, {"x", 0, 0}, state);
    ASSERT_TRUE(block.ok()) << block.error().to_string();
    EXPECT_EQ(state.protocol, kRmq);
    EXPECT_EQ(state.flags, info.protocol_flags);
    ASSERT_EQ(block->warnings.size(), 1u);  // the unknown flag bit
    EXPECT_EQ(std::get<svc::Damage>(block->messages[1].message).from, (Vec3{0, 0.5f, 1.0f}));

    ProtocolState v;
    auto version = decode_server_message(Bytes{4, 0x9a, 0x02, 0, 0}, {"x", 0, 0}, v);
    ASSERT_TRUE(version.ok());
    EXPECT_EQ(v.protocol, kFitzQuake);
}

// ---- the reusing decoder ---------------------------------------------------------------------

// ServerMessageDecoder gives what decode_server_message gives, block after block: the same
// messages, warnings, protocol state and errors (a failed block in between changes nothing for
// the next), while keeping its message storage from block to block.
TEST(ServerMessageDecoder, MatchesTheOneShotDecoderBlockAfterBlock) {
    const std::string file = "demos/a_name_longer_than_inline_storage.dem";
    ProtocolState encoder_state;
    Bytes every_kind =
        encode(test::every_message_kind(ProtocolState{kFitzQuake, 0}), encoder_state);
    Bytes truncated_damage{19, 1};  // svc_damage cut after its first byte
    Bytes two_times = encode({svc::Time{1.5f}, svc::Time{2.0f}}, encoder_state);
    const std::vector<Bytes> blocks = {every_kind, truncated_damage, two_times, every_kind};

    ServerMessageDecoder decoder(file);
    ProtocolState reused_state, one_shot_state;
    const ServerMessage* storage = nullptr;
    for (size_t i = 0; i < blocks.size(); ++i) {
        SCOPED_TRACE("block " + std::to_string(i));
        const uint64_t offset = 1000 * i;
        auto error = decoder.decode(blocks[i], i, offset, reused_state);
        auto expected = decode_server_message(blocks[i], {file, i, offset}, one_shot_state);
        EXPECT_EQ(reused_state, one_shot_state);
        if (!expected) {
            ASSERT_TRUE(error.has_value());
            EXPECT_EQ(error->to_string(), expected.error().to_string());
            continue;
        }
        ASSERT_FALSE(error.has_value()) << error->to_string();
        const DecodedBlock& got = decoder.block();
        EXPECT_EQ(got.warnings, expected->warnings);
        ASSERT_EQ(got.messages.size(), expected->messages.size());
        for (size_t m = 0; m < got.messages.size(); ++m) {
            EXPECT_TRUE(got.messages[m].message == expected->messages[m].message) << m;
            EXPECT_EQ(got.messages[m].offset, expected->messages[m].offset);
            EXPECT_EQ(got.messages[m].size, expected->messages[m].size);
        }
        // The first block is the largest: every later one fits the storage it left.
        if (!storage) storage = &got.messages.front().message;
        EXPECT_EQ(&got.messages.front().message, storage);
    }
}

// ---- encoder refusals ------------------------------------------------------------------------

std::string encode_error(const ServerMessage& m, ProtocolState s) {
    std::vector<ServerMessage> list = {svc::Nop{}, m};
    auto r = encode_server_messages(list, s);
    EXPECT_FALSE(r.ok());
    if (r.ok()) return "";
    EXPECT_EQ(r.error().offset, 1u);  // where message 1 would have started
    return r.error().message;
}

TEST(MessageEncoder, RefusesWhatTheProtocolCannotCarry) {
    const ProtocolState nq{kNetQuake, 0}, fitz{kFitzQuake, 0};
    EXPECT_NE(encode_error(svc::Fog{}, nq).find("message 1 (svc_fog): svc_fog needs protocol 666"),
              std::string::npos);
    EXPECT_NE(encode_error(svc::Skybox{"x"}, nq).find("needs protocol 666"), std::string::npos);

    svc::EntityUpdate u;
    u.bits = U_MODEL;  // bits 8..15 without U_MOREBITS
    EXPECT_NE(encode_error(u, fitz).find("U_MOREBITS"), std::string::npos);
    u.bits = U_MOREBITS | U_MODEL;
    u.model = 300;  // needs U_MODEL2
    EXPECT_NE(encode_error(u, fitz).find("model 300"), std::string::npos);
    u.model = 3;
    u.entity = 256;  // needs U_LONGENTITY
    EXPECT_NE(encode_error(u, fitz).find("U_LONGENTITY"), std::string::npos);
    u.entity = 1;
    u.origin[2] = 5;  // no U_ORIGIN3
    EXPECT_NE(encode_error(u, fitz).find("origin is set but would not be sent"), std::string::npos);

    EXPECT_NE(encode_error(svc::Damage{0, 0, {5000, 0, 0}}, nq).find("outside the encodable"),
              std::string::npos);  // 13.3 fixed point ends at +-4096
    EXPECT_NE(encode_error(svc::Print{std::string("a\0b", 3)}, nq).find("NUL"), std::string::npos);

    svc::Sound big;
    big.field_mask = SND_LARGESOUND;
    big.sound = 300;
    EXPECT_NE(encode_error(big, nq).find("need protocol 666"), std::string::npos);
    big.field_mask = 0;
    EXPECT_NE(encode_error(big, fitz).find("sound index"), std::string::npos);

    svc::ClientData cd;
    cd.weapon_alpha = 5;  // SU_WEAPONALPHA clear
    EXPECT_NE(encode_error(cd, fitz).find("weapon alpha"), std::string::npos);
    cd.weapon_alpha = 0;
    cd.bits = SU_ITEMS | SU_EXTEND1;
    EXPECT_NE(encode_error(cd, nq).find("need protocol 666"), std::string::npos);

    svc::TempEntity t;
    t.type = TE_SPIKE;
    t.end = {1, 0, 0};  // only beams carry an end point
    EXPECT_NE(encode_error(t, nq).find("end point"), std::string::npos);
    svc::ServerInfo si;
    si.protocol = 16;
    EXPECT_NE(encode_error(si, nq).find("unsupported protocol 16"), std::string::npos);
}

}  // namespace
}  // namespace nq

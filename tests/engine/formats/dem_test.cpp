// The .dem container, whole-demo decoding and summary, malformed demos, the real LibreQuake
// demos, and the demotool command line.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <regex>
#include <string>
#include <vector>

#include "common/file_io.h"
#include "formats/dem.h"
#include "formats/demo_summary.h"
#include "formats/message_decoder.h"
#include "formats/message_encoder.h"
#include "support/engine_run.h"
#include "support/raw_bytes.h"
#include "support/synth_dem.h"
#include "support/test_data.h"

namespace nq {
namespace {

using test::read_le32;
using test::read_lef32;

using Bytes = std::vector<uint8_t>;

// ---- independent little helpers (no code under test) ----------------------------------------

void put_i32(Bytes& b, size_t at, int32_t v) {
    for (int i = 0; i < 4; ++i)
        b[at + i] = static_cast<uint8_t>(static_cast<uint32_t>(v) >> (8 * i));
}

// The block layout found by walking the file by hand: offset and length of every block.
struct RawBlock {
    size_t offset;
    int32_t length;
};
std::vector<RawBlock> scan_blocks(const Bytes& b) {
    size_t pos = 0;
    while (b[pos] != '\n') ++pos;
    ++pos;
    std::vector<RawBlock> out;
    while (pos + 16 <= b.size()) {
        int32_t len = read_le32(b, pos);
        if (len < 0 || pos + 16 + static_cast<size_t>(len) > b.size()) break;
        out.push_back({pos, len});
        pos += 16 + static_cast<size_t>(len);
    }
    return out;
}

Bytes load(const std::string& file) {
    auto bytes = read_file(test::lq1_dir() + "/" + file);
    if (!bytes) throw std::runtime_error(bytes.error().to_string());
    return std::move(bytes.value());
}

// ---- container -------------------------------------------------------------------------------

TEST(DemContainer, ParsesTrackLineBlocksAnglesAndOffsets) {
    Bytes file = test::build_demo({{svc::Nop{}}, {svc::Time{2.5f}, svc::Nop{}}, {}}, {}, "7");
    auto demo = parse_dem(file, "synth.dem");
    ASSERT_TRUE(demo.ok()) << demo.error().to_string();
    EXPECT_EQ(demo->cd_track_line, "7");
    EXPECT_EQ(demo->cd_track, 7);
    ASSERT_EQ(demo->blocks.size(), 3u);
    // "7\n" is 2 bytes; then header 16 + 1 byte, header 16 + 6 bytes, header 16 + 0.
    EXPECT_EQ(demo->blocks[0].offset, 2u);
    EXPECT_EQ(demo->blocks[1].offset, 2u + 17u);
    EXPECT_EQ(demo->blocks[2].offset, 2u + 17u + 22u);
    EXPECT_EQ(demo->blocks[1].message_offset(), 2u + 17u + 16u);
    EXPECT_EQ(demo->blocks[1].message, (Bytes{7, 0, 0, 0x20, 0x40, 1}));  // svc_time 2.5f, nop
    EXPECT_EQ(demo->blocks[2].view_angles, (std::array<float, 3>{2.0f, 4.0f, 6.0f}));
    EXPECT_TRUE(demo->warnings.empty());
    EXPECT_EQ(write_dem(demo.value()), file);
}

TEST(DemContainer, TrackLineVariants) {
    auto crlf = parse_dem(test::build_raw_demo({{1}}, "-1\r"), "a.dem");
    ASSERT_TRUE(crlf.ok());
    EXPECT_EQ(crlf->cd_track, -1);
    EXPECT_TRUE(crlf->warnings.empty());

    auto text = parse_dem(test::build_raw_demo({{1}}, "track"), "b.dem");
    ASSERT_TRUE(text.ok());
    EXPECT_EQ(text->cd_track, -1);
    ASSERT_EQ(text->warnings.size(), 1u);
    EXPECT_NE(text->warnings[0].find("not an integer"), std::string::npos);

    auto no_line = parse_dem(Bytes(40, '1'), "c.dem");
    ASSERT_FALSE(no_line.ok());
    EXPECT_EQ(no_line.error().offset, 0u);
    EXPECT_NE(no_line.error().message.find("CD track line"), std::string::npos);

    auto empty = parse_dem(Bytes{}, "d.dem");
    ASSERT_FALSE(empty.ok());
    EXPECT_EQ(empty.error().file, "d.dem");
}

TEST(DemContainer, TruncatedBlockHeaderIsAWarningOrAStrictError) {
    Bytes file = test::build_raw_demo({{1, 1}, {1}});
    const size_t second_block = 3 + 16 + 2;
    file.resize(second_block + 10);  // 10 of the 16 header bytes

    auto lenient = parse_dem(file, "cut.dem");
    ASSERT_TRUE(lenient.ok());
    EXPECT_EQ(lenient->blocks.size(), 1u);
    ASSERT_EQ(lenient->warnings.size(), 1u);
    EXPECT_NE(lenient->warnings[0].find("block 1 (offset 21)"), std::string::npos);
    EXPECT_NE(lenient->warnings[0].find("header truncated"), std::string::npos);

    auto strict = parse_dem(file, "cut.dem", DemParseOptions{false});
    ASSERT_FALSE(strict.ok());
    EXPECT_EQ(strict.error().offset, second_block);
    EXPECT_NE(strict.error().message.find("block 1"), std::string::npos);
}

TEST(DemContainer, TruncatedMessageIsAWarningOrAStrictError) {
    Bytes file = test::build_raw_demo({{1, 1}, {1, 1, 1, 1}});
    file.pop_back();
    auto lenient = parse_dem(file, "cut.dem");
    ASSERT_TRUE(lenient.ok());
    EXPECT_EQ(lenient->blocks.size(), 1u);
    ASSERT_EQ(lenient->warnings.size(), 1u);
    EXPECT_NE(lenient->warnings[0].find("4 bytes truncated to 3"), std::string::npos);

    auto strict = parse_dem(file, "cut.dem", DemParseOptions{false});
    ASSERT_FALSE(strict.ok());
    EXPECT_EQ(strict.error().offset, 21u);
}

TEST(DemContainer, NegativeAndHugeLengthsAreErrorsNamingBlockAndOffset) {
    for (int32_t bad : {-1, INT32_MIN, kMaxDemoMessageBytes + 1, INT32_MAX}) {
        Bytes file = test::build_raw_demo({{1}, {1}});
        put_i32(file, 3 + 17, bad);  // length field of block 1
        auto r = parse_dem(file, "bad.dem");
        ASSERT_FALSE(r.ok()) << bad;
        EXPECT_EQ(r.error().file, "bad.dem");
        EXPECT_EQ(r.error().offset, 20u);
        EXPECT_NE(r.error().message.find("block 1"), std::string::npos);
        EXPECT_NE(r.error().message.find(std::to_string(bad)), std::string::npos);
    }
}

TEST(DemContainer, NonFiniteViewAngleIsAnError) {
    Bytes file = test::build_raw_demo({{1}});
    put_i32(file, 3 + 8, 0x7fc00000);  // NaN as the second view angle
    auto r = parse_dem(file, "nan.dem");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().offset, 11u);
    EXPECT_NE(r.error().message.find("NaN"), std::string::npos);
}

// ---- decoding errors inside blocks ------------------------------------------------------------

// Decodes a demo whose block 1 holds `message`; returns the error (the test fails without one).
Error decode_error(const Bytes& message) {
    Bytes file = test::build_raw_demo({{1}, message});
    auto r = decode_demo(file, "bad.dem");
    EXPECT_FALSE(r.ok());
    return r.ok() ? Error{} : r.error();
}

// Block 1 starts at 3 + 17; its message at 3 + 17 + 16 = 36.
constexpr uint64_t kBlock1Message = 36;

TEST(DemDecodeErrors, UnknownSvcNamesBlockOffsetAndMessage) {
    Error e = decode_error({1, 1, 35});
    EXPECT_EQ(e.file, "bad.dem");
    EXPECT_EQ(e.offset, kBlock1Message + 2);
    EXPECT_NE(e.message.find("block 1"), std::string::npos) << e.message;
    EXPECT_NE(e.message.find("svc 35"), std::string::npos) << e.message;
    EXPECT_NE(e.message.find("unknown server message number 35"), std::string::npos);
    EXPECT_NE(e.message.find("previous: svc_nop"), std::string::npos);
}

TEST(DemDecodeErrors, MessageEndingMidFieldNamesTheMessage) {
    Error e = decode_error({1, 7, 0, 0});  // svc_time with 2 of its 4 bytes
    EXPECT_EQ(e.offset, kBlock1Message + 2);
    EXPECT_NE(e.message.find("block 1: svc_time at message byte 1"), std::string::npos)
        << e.message;
    EXPECT_NE(e.message.find("unexpected end"), std::string::npos);

    Error s = decode_error({8, 'h', 'i'});  // svc_print without its NUL
    EXPECT_NE(s.message.find("svc_print"), std::string::npos);
    EXPECT_NE(s.message.find("not terminated"), std::string::npos);

    Error u = decode_error({0x80 | 0x01});  // update with U_MOREBITS and nothing more
    EXPECT_EQ(u.offset, kBlock1Message + 1);
    EXPECT_NE(u.message.find("entity_update"), std::string::npos);
}

TEST(DemDecodeErrors, IllegibleObsoleteAndInvalidFields) {
    EXPECT_NE(decode_error({0}).message.find("svc_bad"), std::string::npos);
    EXPECT_NE(decode_error({21}).message.find("obsolete"), std::string::npos);
    Error te = decode_error({23, 14, 0, 0, 0, 0, 0, 0});
    EXPECT_NE(te.message.find("unknown temp entity type 14"), std::string::npos);
    EXPECT_EQ(te.offset, kBlock1Message + 1);
    Error proto = decode_error({11, 0x10, 0, 0, 0});  // serverinfo, protocol 16
    EXPECT_NE(proto.message.find("unsupported protocol 16"), std::string::npos);
    Error version = decode_error({4, 0x0f, 0, 0, 1});
    EXPECT_NE(version.message.find("svc_version"), std::string::npos);
    Error neg = decode_error({22, 0xff, 0xff});  // spawnbaseline of entity -1
    EXPECT_NE(neg.message.find("negative entity number -1"), std::string::npos);
    Error nehahra = decode_error({0x81, 0x80, 5});  // bit 15 under protocol 15
    EXPECT_NE(nehahra.message.find("U_TRANS"), std::string::npos);
    Error nan_time = decode_error({7, 0, 0, 0xc0, 0x7f});
    EXPECT_NE(nan_time.message.find("NaN"), std::string::npos);
}

TEST(DemDecodeErrors, CaughtInTheMiddleOfARealLookingDemo) {
    // A protocol 666 demo with a garbage byte appended to block 3: the error must point at the
    // exact file offset of that byte.
    protocol::ProtocolState fitz{protocol::kFitzQuake, 0};
    std::vector<ServerMessage> info = {test::every_message_kind(fitz).front()};
    Bytes file = test::build_demo({info, {svc::Nop{}}, {svc::Nop{}}, {svc::Time{1}}});
    auto demo = parse_dem(file, "x.dem");
    ASSERT_TRUE(demo.ok());
    const uint64_t block3 = demo->blocks[3].offset;
    put_i32(file, block3, 6);
    file.push_back(39);  // unassigned svc number
    auto r = decode_demo(file, "x.dem");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().offset, block3 + 16 + 5);
    EXPECT_NE(r.error().message.find("block 3: svc 39"), std::string::npos) << r.error().message;
}

// ---- summary of synthetic demos -------------------------------------------------------------

svc::ServerInfo info_for(const std::string& map) {
    svc::ServerInfo si;
    si.protocol = protocol::kFitzQuake;
    si.level_name = "Level " + map;
    si.models = {"maps/" + map + ".bsp", "progs/player.mdl"};
    si.sounds = {"misc/null.wav"};
    return si;
}

TEST(DemoSummary, CountsTimesMapsAndKinds) {
    svc::EntityUpdate u;
    u.entity = 1;
    Bytes file = test::build_demo({{info_for("a")},
                                   {svc::Time{1.0f}, u},
                                   {svc::Time{2.0f}, u, u},
                                   {info_for("b")},
                                   {svc::Time{0.5f}},
                                   {svc::Time{0.75f}}});
    auto s = summarize_demo_file(file, "s.dem");
    ASSERT_TRUE(s.ok()) << s.error().to_string();
    EXPECT_TRUE(s->warnings.empty()) << s->warnings.front();
    EXPECT_EQ(s->protocol, 666);
    EXPECT_EQ(s->map, "maps/a.bsp");
    EXPECT_EQ(s->level_name, "Level a");
    EXPECT_EQ(s->maps, (std::vector<std::string>{"maps/a.bsp", "maps/b.bsp"}));
    EXPECT_EQ(s->models, (std::vector<std::string>{"maps/a.bsp", "progs/player.mdl"}));
    EXPECT_EQ(s->blocks, 6u);
    EXPECT_EQ(s->messages, 9u);
    EXPECT_EQ(s->entity_updates, 3u);
    EXPECT_EQ(s->time_messages, 4u);
    EXPECT_EQ(*s->first_time, 1.0f);
    EXPECT_EQ(*s->last_time, 0.75f);
    EXPECT_EQ(s->duration, 0.75f);              // the last svc_time
    EXPECT_EQ(s->playback_time, 1.0f + 0.25f);  // (2 - 1) on map a + (0.75 - 0.5) on map b
    std::map<std::string, std::pair<size_t, size_t>> histogram;
    for (const auto& k : s->histogram) histogram[k.name] = {k.count, k.bytes};
    EXPECT_EQ(histogram.size(), 3u);
    EXPECT_EQ(histogram["svc_time"], (std::pair<size_t, size_t>{4, 20}));      // 1 + float each
    EXPECT_EQ(histogram["entity_update"], (std::pair<size_t, size_t>{3, 6}));  // bits + entity
    EXPECT_EQ(histogram["svc_serverinfo"].first, 2u);
}

TEST(DemoSummary, WarnsAboutTimeGoingBackwardsAndMissingServerInfo) {
    Bytes file = test::build_demo({{svc::Time{2.0f}}, {svc::Time{1.0f}}});
    auto s = summarize_demo_file(file, "s.dem");
    ASSERT_TRUE(s.ok());
    EXPECT_EQ(s->protocol, 15);  // nothing said otherwise
    ASSERT_EQ(s->warnings.size(), 2u);
    EXPECT_NE(s->warnings[0].find("backwards"), std::string::npos);
    EXPECT_NE(s->warnings[1].find("no svc_serverinfo"), std::string::npos);
}

// ---- real demos -------------------------------------------------------------------------------

class RealDemo : public ::testing::TestWithParam<const char*> {};

// Decoding a real demo takes a while under the sanitizers: each file is decoded once.
const DecodedDemo& decoded_real(const std::string& file) {
    static std::map<std::string, DecodedDemo> cache;
    auto it = cache.find(file);
    if (it != cache.end()) return it->second;
    auto decoded = decode_demo(load(file), file);
    if (!decoded) throw std::runtime_error(decoded.error().to_string());
    return cache.emplace(file, std::move(decoded.value())).first->second;
}

TEST_P(RealDemo, DecodesFullyAsProtocol666OnStart) {
    const DecodedDemo* decoded = nullptr;
    ASSERT_NO_THROW(decoded = &decoded_real(GetParam()));
    DemoSummary s = summarize_demo(*decoded, GetParam());
    EXPECT_TRUE(s.warnings.empty()) << s.warnings.front();
    EXPECT_EQ(s.protocol, 666);
    EXPECT_EQ(s.map, "maps/start.bsp");
    EXPECT_EQ(s.cd_track, -1);
    // The FitzQuake server announces itself in the first svc_print of the first block.
    const auto& first = decoded->blocks.front().messages.front().message;
    ASSERT_TRUE(std::holds_alternative<svc::Print>(first));
    EXPECT_NE(std::get<svc::Print>(first).text.find("FITZQUAKE"), std::string::npos);
}

TEST_P(RealDemo, BlocksMatchAnIndependentScan) {
    Bytes file = load(GetParam());
    std::vector<RawBlock> raw = scan_blocks(file);
    const DecodedDemo* decoded = &decoded_real(GetParam());
    ASSERT_EQ(decoded->demo.blocks.size(), raw.size());
    size_t total = 0;
    for (size_t i = 0; i < raw.size(); ++i) {
        EXPECT_EQ(decoded->demo.blocks[i].offset, raw[i].offset);
        EXPECT_EQ(decoded->demo.blocks[i].message.size(), static_cast<size_t>(raw[i].length));
        EXPECT_EQ(decoded->demo.blocks[i].view_angles[1], read_lef32(file, raw[i].offset + 8));
        total += static_cast<size_t>(raw[i].length);
    }
    // The messages tile every block exactly: the histogram's bytes add up to all block bytes.
    DemoSummary s = summarize_demo(*decoded, GetParam());
    size_t histogram_bytes = 0, histogram_count = 0;
    for (const auto& k : s.histogram) {
        histogram_bytes += k.bytes;
        histogram_count += k.count;
    }
    EXPECT_EQ(histogram_bytes, total);
    EXPECT_EQ(s.message_bytes, total);
    EXPECT_EQ(histogram_count, s.messages);
    EXPECT_EQ(s.blocks, raw.size());
}

TEST_P(RealDemo, TimeIsMonotonicPerMapAndDurationIsTheLastTime) {
    Bytes file = load(GetParam());
    // Independent scan: a server frame starts its message with svc_time (7) and a float.
    std::vector<float> frame_times;
    for (const RawBlock& b : scan_blocks(file)) {
        if (b.length >= 5 && file[b.offset + 16] == 7)
            frame_times.push_back(read_lef32(file, b.offset + 17));
    }
    ASSERT_FALSE(frame_times.empty());

    const DecodedDemo* decoded = &decoded_real(GetParam());
    float last = -1;
    size_t times = 0;
    for (const auto& block : decoded->blocks) {
        for (const auto& m : block.messages) {
            if (std::holds_alternative<svc::ServerInfo>(m.message)) last = -1;  // clock restarts
            if (const auto* t = std::get_if<svc::Time>(&m.message)) {
                EXPECT_GE(t->time, last);
                last = t->time;
                ++times;
            }
        }
    }
    DemoSummary s = summarize_demo(*decoded, GetParam());
    EXPECT_EQ(times, frame_times.size());
    EXPECT_EQ(s.time_messages, frame_times.size());
    EXPECT_GT(s.duration, 0.0f);
    EXPECT_EQ(s.duration, frame_times.back());
    EXPECT_EQ(*s.last_time, frame_times.back());
    EXPECT_EQ(*s.first_time, frame_times.front());
    EXPECT_GT(s.playback_time, 0.0f);
}

TEST_P(RealDemo, ReencodingEveryBlockGivesTheSameBytes) {
    Bytes file = load(GetParam());
    std::vector<RawBlock> raw = scan_blocks(file);
    const DecodedDemo* decoded = &decoded_real(GetParam());
    ASSERT_EQ(decoded->blocks.size(), raw.size());
    protocol::ProtocolState state;
    for (size_t i = 0; i < decoded->blocks.size(); ++i) {
        std::vector<ServerMessage> messages;
        for (const auto& m : decoded->blocks[i].messages) messages.push_back(m.message);
        auto bytes = encode_server_messages(messages, state);
        ASSERT_TRUE(bytes.ok()) << "block " << i << ": " << bytes.error().to_string();
        auto original = file.begin() + static_cast<ptrdiff_t>(raw[i].offset + 16);
        ASSERT_EQ(bytes.value(), Bytes(original, original + raw[i].length)) << "block " << i;
    }
}

INSTANTIATE_TEST_SUITE_P(Lq1, RealDemo, ::testing::Values("demo.dem", "demo2.dem"));

// What maps/start.bsp says, read with a few lines of independent code: the world model's
// bounding box (models lump 14, first model) and the origin of an entity by classname.
struct StartMap {
    float mins[3], maxs[3];
    std::string entities;
};
StartMap read_start_map() {
    Bytes bsp = load("maps/start.bsp");
    StartMap m;
    const size_t entities_lump = 4 + 0 * 8, models_lump = 4 + 14 * 8;
    int32_t models_at = read_le32(bsp, models_lump);
    for (int i = 0; i < 3; ++i) {
        m.mins[i] = read_lef32(bsp, models_at + 4 * i);
        m.maxs[i] = read_lef32(bsp, models_at + 12 + 4 * i);
    }
    m.entities.assign(reinterpret_cast<const char*>(bsp.data()) + read_le32(bsp, entities_lump),
                      read_le32(bsp, entities_lump + 4));
    return m;
}
std::array<float, 3> origin_of(const std::string& entities, const std::string& classname) {
    std::regex block("\\{[^}]*\"classname\" \"" + classname + "\"[^}]*\\}");
    std::smatch b;
    if (!std::regex_search(entities, b, block)) throw std::runtime_error("no " + classname);
    std::regex origin("\"origin\" \"(-?[0-9.]+) (-?[0-9.]+) (-?[0-9.]+)\"");
    std::smatch o;
    std::string text = b.str();
    if (!std::regex_search(text, o, origin)) throw std::runtime_error("no origin");
    return {std::stof(o[1]), std::stof(o[2]), std::stof(o[3])};
}

bool inside(const StartMap& m, const Vec3& p) {
    for (int i = 0; i < 3; ++i) {
        if (p[i] < m.mins[i] - 1 || p[i] > m.maxs[i] + 1) return false;
    }
    return true;
}

TEST_P(RealDemo, EntityPositionsAgreeWithTheMap) {
    StartMap map = read_start_map();
    const DecodedDemo* decoded = &decoded_real(GetParam());
    const auto& info = std::get<svc::ServerInfo>(decoded->blocks[0].messages[1].message);
    // The model index of the exploding box model (precache lists are 1-based).
    int explobox_model = 0;
    for (size_t i = 0; i < info.models.size(); ++i) {
        if (info.models[i] == "maps/b_exbox2.bsp") explobox_model = static_cast<int>(i + 1);
    }
    ASSERT_GT(explobox_model, 0);

    int view_entity = -1, baselines_checked = 0, point_baselines = 0, player_origins = 0;
    int statics = 0;
    for (const auto& block : decoded->blocks) {
        for (const auto& m : block.messages) {
            if (const auto* v = std::get_if<svc::SetView>(&m.message)) view_entity = v->entity;
            const auto* b = std::get_if<svc::SpawnBaseline>(&m.message);
            if (b && b->state.model == explobox_model) {
                // misc_explobox2 spawns where the map puts it.
                EXPECT_EQ(b->state.origin, origin_of(map.entities, "misc_explobox2"));
                ++baselines_checked;
            }
            // Point entities (not the world, players or brush models, whose origin is an
            // offset) start inside the world's bounding box.
            if (b && b->entity > info.max_clients && b->state.model > 1 &&
                info.models.at(b->state.model - 1)[0] != '*') {
                EXPECT_TRUE(inside(map, b->state.origin)) << "entity " << b->entity;
                ++point_baselines;
            }
            if (const auto* s = std::get_if<svc::SpawnStaticSound>(&m.message)) {
                EXPECT_TRUE(inside(map, s->fields.origin));
                ++statics;
            }
            const auto* u = std::get_if<svc::EntityUpdate>(&m.message);
            const uint32_t all_origin =
                protocol::U_ORIGIN1 | protocol::U_ORIGIN2 | protocol::U_ORIGIN3;
            if (u && u->entity == view_entity && (u->bits & all_origin) == all_origin) {
                EXPECT_TRUE(inside(map, u->origin))
                    << u->origin[0] << " " << u->origin[1] << " " << u->origin[2];
                ++player_origins;
            }
        }
    }
    EXPECT_EQ(view_entity, 1);  // single player: the player is entity 1
    EXPECT_GE(baselines_checked, 1);
    EXPECT_GT(point_baselines, 20);
    EXPECT_GT(statics, 0);
    EXPECT_GT(player_origins, 100);
}

// ---- demotool ---------------------------------------------------------------------------------

test::ProcessResult run_demotool(const std::vector<std::string>& args) {
    return test::run_tool("demotool", args);
}

TEST(Demotool, InfoJsonDumpAndErrors) {
    std::string demo = test::lq1_dir() + "/demo.dem";
    test::ProcessResult json = run_demotool({"info", demo, "--json"});
    ASSERT_EQ(json.exit_code, 0) << json.describe();
    EXPECT_NE(json.out.find("\"protocol\": 666"), std::string::npos) << json.out.substr(0, 400);
    EXPECT_NE(json.out.find("\"map\": \"maps/start.bsp\""), std::string::npos);
    EXPECT_NE(json.out.find("\"name\": \"entity_update\""), std::string::npos);

    test::ProcessResult text = run_demotool({"info", demo});
    ASSERT_EQ(text.exit_code, 0);
    EXPECT_NE(text.out.find("protocol:       666 (FitzQuake)"), std::string::npos);
    EXPECT_NE(text.out.find("duration:"), std::string::npos);

    test::ProcessResult dump = run_demotool({"dump", demo, "--from", "1", "--count", "1"});
    ASSERT_EQ(dump.exit_code, 0);
    EXPECT_NE(dump.out.find("block 1  offset"), std::string::npos);
    EXPECT_NE(dump.out.find("svc_spawnbaseline"), std::string::npos);
    EXPECT_EQ(dump.out.find("block 2 "), std::string::npos);

    EXPECT_EQ(run_demotool({"frobnicate", demo}).exit_code, 2);
    test::ProcessResult missing = run_demotool({"info", "/nonexistent.dem"});
    EXPECT_EQ(missing.exit_code, 1);
}

}  // namespace
}  // namespace nq

// BSP maps: every LibreQuake map (counts re-derived here from the raw header, PVS rows decoded
// by an independent brute-force decoder, hull queries at known places), synthetic box rooms in
// BSP29 / BSP2 / 2PSB, and one malformed file for every kind of bad count, offset and index.
#include <gtest/gtest.h>

#include <climits>
#include <cmath>
#include <cstring>
#include <fstream>
#include <functional>
#include <iterator>
#include <random>

#include "formats/bsp.h"
#include "formats/entities.h"
#include "support/raw_bytes.h"
#include "support/synth_bsp.h"
#include "support/test_data.h"

namespace nq {
namespace {

using test::raw_file;
using test::read_le32;

using test::SynthBsp;
namespace room = test::box_room;

// ---- Independent raw access (the format as documented, not the parser's tables) -----------

void put_i32(std::vector<uint8_t>& b, size_t at, int32_t v) {
    std::memcpy(b.data() + at, &v, 4);
}

// Lump numbers and BSP29 record sizes, from the format description.
enum RawLump {
    kEnt,
    kPlanes,
    kTex,
    kVerts,
    kVis,
    kNodes,
    kTexinfo,
    kFaces,
    kLight,
    kClip,
    kLeafs,
    kMarks,
    kEdges,
    kSurfedges,
    kModels
};
struct RawSpan {
    size_t offset, length;
};
RawSpan raw_lump(const std::vector<uint8_t>& b, int lump) {
    return {size_t(read_le32(b, 4 + 8 * lump)), size_t(read_le32(b, 8 + 8 * lump))};
}

Bsp parse_ok(const std::vector<uint8_t>& bytes, const std::string& name = "test.bsp") {
    auto bsp = parse_bsp(bytes, name);
    if (!bsp) throw std::runtime_error(bsp.error().to_string());
    return std::move(bsp).value();
}

bool has_warning(const std::vector<std::string>& warnings, const std::string& text) {
    for (const auto& w : warnings) {
        if (w.find(text) != std::string::npos) return true;
    }
    return false;
}

// Brute-force PVS decoder straight from the format description, byte by byte.
std::vector<uint8_t> brute_force_row(const std::vector<uint8_t>& vis, size_t offset, size_t len) {
    std::vector<uint8_t> row;
    size_t i = offset;
    while (row.size() < len) {
        if (vis.at(i) != 0) {
            row.push_back(vis.at(i++));
        } else {
            const size_t n = vis.at(i + 1);
            i += 2;
            for (size_t k = 0; k < n; ++k) row.push_back(0);
        }
    }
    row.resize(len);
    return row;
}

struct RealMap {
    std::string path;
    std::vector<uint8_t> raw;
    Bsp bsp;
    bool is_item_box() const {  // maps/b_*.bsp are brush models of item boxes, not levels
        return path.substr(path.find_last_of('/') + 1, 2) == "b_";
    }
};

const std::vector<RealMap>& real_maps() {
    static const std::vector<RealMap> maps = [] {
        std::vector<RealMap> out;
        for (const auto& path : test::lq1_files("maps", ".bsp")) {
            RealMap m{path, raw_file(path), {}};
            m.bsp = parse_ok(m.raw, path);
            out.push_back(std::move(m));
        }
        return out;
    }();
    return maps;
}

const RealMap& start_map() {
    for (const auto& m : real_maps()) {
        if (m.path.ends_with("/start.bsp")) return m;
    }
    throw std::runtime_error("maps/start.bsp missing");
}

BspVec3 player_start(const Bsp& bsp) {
    auto ents = parse_entities(bsp.entities, bsp.name, bsp.entities_offset);
    if (!ents) throw std::runtime_error(ents.error().to_string());
    auto starts = find_entities(*ents, "info_player_start");
    if (starts.empty()) throw std::runtime_error(bsp.name + ": no info_player_start");
    auto origin = find_vec3(*starts[0], "origin");
    if (!origin) throw std::runtime_error(bsp.name + ": info_player_start without origin");
    return *origin;
}

// ---- LibreQuake maps ----------------------------------------------------------------------

TEST(BspReal, EveryMapParsesWithCountsMatchingItsLumps) {
    ASSERT_GE(real_maps().size(), 3u);
    const struct {
        int lump;
        size_t record;
    } kRecords[] = {{kPlanes, 20}, {kVerts, 12},    {kNodes, 24}, {kTexinfo, 40},
                    {kFaces, 20},  {kClip, 8},      {kLeafs, 28}, {kMarks, 2},
                    {kEdges, 4},   {kSurfedges, 4}, {kModels, 64}};
    for (const auto& m : real_maps()) {
        SCOPED_TRACE(m.path);
        const Bsp& bsp = m.bsp;
        ASSERT_EQ(read_le32(m.raw, 0), 29);
        EXPECT_EQ(bsp.format, BspFormat::bsp29);
        const size_t counts[] = {
            bsp.planes.size(),    bsp.vertices.size(),     bsp.nodes.size(),
            bsp.texinfo.size(),   bsp.faces.size(),        bsp.hulls[1].clipnodes.size(),
            bsp.leafs.size(),     bsp.marksurfaces.size(), bsp.edges.size(),
            bsp.surfedges.size(), bsp.models.size()};
        for (size_t i = 0; i < std::size(kRecords); ++i) {
            const RawSpan lump = raw_lump(m.raw, kRecords[i].lump);
            EXPECT_EQ(lump.length % kRecords[i].record, 0u);
            EXPECT_EQ(counts[i], lump.length / kRecords[i].record) << "lump " << kRecords[i].lump;
        }
        EXPECT_EQ(bsp.hulls[0].clipnodes.size(), bsp.nodes.size());
        EXPECT_EQ(bsp.hulls[2].clipnodes.size(), bsp.hulls[1].clipnodes.size());
        EXPECT_EQ(bsp.visibility.size(), raw_lump(m.raw, kVis).length);
        EXPECT_EQ(bsp.lighting.size(), raw_lump(m.raw, kLight).length);
        const RawSpan tex = raw_lump(m.raw, kTex);
        EXPECT_EQ(bsp.textures.size(), size_t(read_le32(m.raw, tex.offset)));
        const RawSpan ent = raw_lump(m.raw, kEnt);
        const char* text = reinterpret_cast<const char*>(m.raw.data() + ent.offset);
        EXPECT_EQ(bsp.entities, std::string(text, strnlen(text, ent.length)));
        EXPECT_EQ(bsp.entities_offset, ent.offset);
    }
}

TEST(BspReal, StartIsBsp29WithNineModels) {
    const RealMap& m = start_map();
    EXPECT_EQ(std::string(bsp_format_name(m.bsp.format)), "BSP29");
    EXPECT_EQ(m.bsp.models.size(), raw_lump(m.raw, kModels).length / 64);
    // Model 0's fields, read raw: 9 floats, then headnodes[4], visleafs, firstface, numfaces.
    const size_t model0 = raw_lump(m.raw, kModels).offset;
    const BspModel& world = m.bsp.models[0];
    EXPECT_EQ(world.headnodes[0], read_le32(m.raw, model0 + 36));
    EXPECT_EQ(world.headnodes[1], read_le32(m.raw, model0 + 40));
    EXPECT_EQ(world.headnodes[2], read_le32(m.raw, model0 + 44));
    EXPECT_EQ(world.visleafs, uint32_t(read_le32(m.raw, model0 + 52)));
    EXPECT_EQ(world.first_face, 0u);
    EXPECT_EQ(world.num_faces, uint32_t(read_le32(m.raw, model0 + 60)));
}

TEST(BspReal, WorldspawnComesFirstAndLevelsHaveAPlayerStart) {
    for (const auto& m : real_maps()) {
        SCOPED_TRACE(m.path);
        auto ents = parse_entities(m.bsp.entities, m.path, m.bsp.entities_offset);
        ASSERT_TRUE(ents) << ents.error().to_string();
        ASSERT_FALSE(ents->entities.empty());
        EXPECT_EQ(classname(ents->entities[0]), "worldspawn");
        if (m.is_item_box()) continue;
        auto starts = find_entities(*ents, "info_player_start");
        ASSERT_GE(starts.size(), 1u);
        EXPECT_TRUE(find_vec3(*starts[0], "origin").has_value());
        // Brush entities name their submodel "*N"; every such N must be a model of the map.
        for (const auto& e : ents->entities) {
            auto model = find_value(e, "model");
            if (model && model->starts_with("*")) {
                EXPECT_LT(std::stoul(std::string(model->substr(1))), m.bsp.models.size());
            }
        }
    }
}

TEST(BspReal, PlayerStartIsOpenAndFarOutsideIsSolid) {
    for (const auto& m : real_maps()) {
        if (m.is_item_box()) continue;
        SCOPED_TRACE(m.path);
        const BspVec3 origin = player_start(m.bsp);
        EXPECT_EQ(point_contents(m.bsp, 0, origin), bsp_contents::empty);
        EXPECT_EQ(point_contents(m.bsp, 1, origin), bsp_contents::empty);  // a player fits
        const BspVec3 far{40000, -40000, 40000};
        for (int hull = 0; hull < 3; ++hull) {
            EXPECT_EQ(point_contents(m.bsp, hull, far), bsp_contents::solid) << "hull " << hull;
        }
        const uint32_t leaf = leaf_at(m.bsp, origin);
        EXPECT_GE(leaf, 1u);
        EXPECT_EQ(m.bsp.leafs[leaf].contents, bsp_contents::empty);
    }
}

TEST(BspReal, TraceDownFromPlayerStartFindsTheFloor) {
    for (const auto& m : real_maps()) {
        if (m.is_item_box()) continue;
        SCOPED_TRACE(m.path);
        const BspVec3 origin = player_start(m.bsp);
        const BspTrace tr = trace_down(m.bsp, origin, 4096);
        ASSERT_TRUE(tr.hit());
        EXPECT_FALSE(tr.start_solid);
        EXPECT_GT(tr.plane_normal[2], 0.7f);  // a floor, not a wall
        const float drop = origin[2] - tr.end[2];
        EXPECT_GT(drop, 0.f);
        EXPECT_LT(drop, 128.f);  // player starts stand on (or just above) the floor
        EXPECT_NEAR(tr.fraction, drop / 4096, 1e-4);
        EXPECT_NE(point_contents(m.bsp, 0, tr.end), bsp_contents::solid);
        EXPECT_EQ(point_contents(m.bsp, 0, {tr.end[0], tr.end[1], tr.end[2] - 2}),
                  bsp_contents::solid);
    }
}

TEST(BspReal, PvsRowsMatchABruteForceDecoder) {
    const RealMap& m = start_map();
    const Bsp& bsp = m.bsp;
    const size_t model0 = raw_lump(m.raw, kModels).offset;
    const size_t visleafs = size_t(read_le32(m.raw, model0 + 52));
    const size_t row_bytes = (visleafs + 7) / 8;
    ASSERT_EQ(pvs_row_bytes(bsp), row_bytes);
    const RawSpan vis = raw_lump(m.raw, kVis);
    const RawSpan leafs = raw_lump(m.raw, kLeafs);
    const std::vector<uint8_t> vis_bytes(m.raw.begin() + vis.offset,
                                         m.raw.begin() + vis.offset + vis.length);
    EXPECT_EQ(decompress_vis(bsp, 0), std::vector<uint8_t>(row_bytes, 0));  // solid sees nothing
    size_t rows_with_data = 0;
    for (uint32_t leaf = 1; leaf <= visleafs; ++leaf) {
        SCOPED_TRACE("leaf " + std::to_string(leaf));
        const int32_t visofs = read_le32(m.raw, leafs.offset + 28 * leaf + 4);
        const auto row = decompress_vis(bsp, leaf);
        ASSERT_EQ(row.size(), row_bytes);
        if (visofs < 0) {
            for (uint32_t other = 1; other <= visleafs; ++other) {
                EXPECT_TRUE(pvs_contains(row, other));
            }
            continue;
        }
        ++rows_with_data;
        EXPECT_EQ(row, brute_force_row(vis_bytes, size_t(visofs), row_bytes));
        EXPECT_TRUE(pvs_contains(row, leaf)) << "a leaf always sees itself";
    }
    EXPECT_GT(rows_with_data, 0u);
    const uint32_t here = leaf_at(bsp, player_start(bsp));
    EXPECT_TRUE(pvs_contains(decompress_vis(bsp, here), here));
}

TEST(BspReal, TexturesKeepEveryMipLevelAndMissingOnesArePlaceholders) {
    for (const auto& m : real_maps()) {
        SCOPED_TRACE(m.path);
        const RawSpan lump = raw_lump(m.raw, kTex);
        size_t missing = 0;
        for (size_t i = 0; i < m.bsp.textures.size(); ++i) {
            const BspTexture& t = m.bsp.textures[i];
            const int32_t miptex = read_le32(m.raw, lump.offset + 4 + 4 * i);
            if (miptex == -1) {
                ++missing;
                EXPECT_TRUE(t.placeholder);
                continue;
            }
            ASSERT_FALSE(t.placeholder) << t.name;
            const size_t base = lump.offset + size_t(miptex);
            EXPECT_EQ(t.name, std::string(reinterpret_cast<const char*>(&m.raw[base])));
            EXPECT_EQ(t.width, uint32_t(read_le32(m.raw, base + 16)));
            EXPECT_EQ(t.height, uint32_t(read_le32(m.raw, base + 20)));
            for (int level = 0; level < 4; ++level) {
                const BspMipLevel& mip = t.mips[level];
                EXPECT_EQ(mip.width, t.width >> level);
                EXPECT_EQ(mip.height, t.height >> level);
                const size_t at = base + size_t(read_le32(m.raw, base + 24 + 4 * level));
                ASSERT_EQ(mip.pixels.size(), size_t(mip.width) * mip.height);
                EXPECT_TRUE(std::equal(mip.pixels.begin(), mip.pixels.end(), m.raw.begin() + at));
            }
        }
        size_t warned = 0;
        for (const auto& w : m.bsp.warnings) warned += w.find("offset -1") != std::string::npos;
        EXPECT_EQ(warned, missing);
    }
}

TEST(BspReal, LitFacesHaveLightmapsInsideTheLightingLump) {
    for (const auto& m : real_maps()) {
        SCOPED_TRACE(m.path);
        size_t lit = 0;
        for (const BspFace& f : m.bsp.faces) {
            if (!f.has_lightmap()) continue;
            ++lit;
            EXPECT_EQ(f.texture_mins[0] % 16, 0);
            EXPECT_EQ(f.extents[0] % 16, 0);
            EXPECT_EQ(f.lightmap_width, uint32_t(f.extents[0] / 16 + 1));
            EXPECT_EQ(f.lightmap_height, uint32_t(f.extents[1] / 16 + 1));
            EXPECT_LE(f.light_offset + f.lightmap_samples() * f.num_styles, m.bsp.lighting.size());
        }
        EXPECT_GT(lit, 0u);
    }
}

// ---- Synthetic box rooms in every format ---------------------------------------------------

class BspSynth : public ::testing::TestWithParam<BspFormat> {};

std::string format_label(const ::testing::TestParamInfo<BspFormat>& info) {
    return info.param == BspFormat::bsp2psb ? "P2PSB" : bsp_format_name(info.param);
}

INSTANTIATE_TEST_SUITE_P(AllFormats, BspSynth,
                         ::testing::Values(BspFormat::bsp29, BspFormat::bsp2, BspFormat::bsp2psb),
                         format_label);

TEST_P(BspSynth, BoxRoomRoundTrips) {
    const SynthBsp synth = test::make_box_room();
    const auto bytes = test::write_bsp(synth, GetParam());
    const Bsp bsp = parse_ok(bytes);
    EXPECT_EQ(bsp.format, GetParam());
    EXPECT_TRUE(bsp.warnings.empty()) << bsp.warnings.front();
    EXPECT_EQ(bsp.planes.size(), synth.planes.size());
    EXPECT_EQ(bsp.vertices.size(), 16u);    // two boxes, 8 corners each
    EXPECT_EQ(bsp.edges.size(), 1u + 24u);  // the unused edge 0, then 12 per box
    EXPECT_EQ(bsp.surfedges.size(), 48u);
    EXPECT_EQ(bsp.faces.size(), 12u);
    EXPECT_EQ(bsp.nodes.size(), 12u);
    EXPECT_EQ(bsp.leafs.size(), 3u);
    EXPECT_EQ(bsp.hulls[1].clipnodes.size(), 24u);
    EXPECT_EQ(bsp.models.size(), 2u);
    EXPECT_EQ(bsp.entities, synth.entities);
    for (size_t i = 0; i < bsp.vertices.size(); ++i) EXPECT_EQ(bsp.vertices[i], synth.vertices[i]);
    EXPECT_EQ(bsp.surfedges, synth.surfedges);
    EXPECT_EQ(bsp.leafs[0].contents, bsp_contents::solid);
    EXPECT_EQ(bsp.leafs[room::kRoomLeaf].contents, bsp_contents::empty);
    EXPECT_EQ(bsp.leafs[room::kRoomLeaf].num_marksurfaces, 6u);
    EXPECT_EQ(bsp.leafs[room::kRoomLeaf].mins, room::kRoomMins);  // whole numbers survive shorts
    EXPECT_EQ(bsp.nodes[0].children[1], -1);  // behind the x = -128 wall: leaf 0
    EXPECT_EQ(bsp.nodes[5].children[1], -int32_t(room::kRoomLeaf) - 1);
    EXPECT_EQ(bsp.models[1].first_face, 6u);
    EXPECT_EQ(bsp.models[1].mins, room::kCrateMins);
    EXPECT_EQ(bsp.models[1].headnodes[0], 6);
}

TEST_P(BspSynth, TexturesAndLightmapsHaveTheirKnownSizes) {
    const Bsp bsp = parse_ok(test::write_bsp(test::make_box_room(), GetParam()));
    ASSERT_EQ(bsp.textures.size(), 2u);
    EXPECT_EQ(bsp.textures[1].name, "floor");
    EXPECT_EQ(bsp.textures[1].width, 32u);
    EXPECT_EQ(bsp.textures[1].height, 16u);
    for (int level = 0; level < 4; ++level) {
        const BspMipLevel& mip = bsp.textures[1].mips[level];
        ASSERT_EQ(mip.width, 32u >> level);
        ASSERT_EQ(mip.height, 16u >> level);
        EXPECT_EQ(mip.pixels[mip.width + 1], test::synth_texture_pixel(1, level, 1, 1));
        EXPECT_EQ(mip.pixels.back(),
                  test::synth_texture_pixel(1, level, mip.width - 1, mip.height - 1));
    }
    // Room walls span 256 texels across and 192 up (s, t = the other two axes): 256/16+1 = 17
    // by 192/16+1 = 13 samples; the floor 17 x 17; the 32-unit crate sides 3 x 3.
    const BspFace& wall = bsp.faces[0];
    EXPECT_EQ(wall.texture_mins[0], -128);
    EXPECT_EQ(wall.extents[0], 256);
    EXPECT_EQ(wall.extents[1], 192);
    EXPECT_EQ(wall.lightmap_width, 17u);
    EXPECT_EQ(wall.lightmap_height, 13u);
    EXPECT_EQ(bsp.faces[4].lightmap_width * bsp.faces[4].lightmap_height, 289u);
    const BspFace& ceiling = bsp.faces[5];
    EXPECT_EQ(ceiling.num_styles, 2u);
    EXPECT_EQ(ceiling.lightmap_samples(), 289u);
    for (size_t i = 6; i < 12; ++i) EXPECT_EQ(bsp.faces[i].lightmap_samples(), 9u);
    EXPECT_EQ(bsp.lighting.size(), 4u * 221 + 289 + 2 * 289 + 6 * 9);
}

TEST_P(BspSynth, HullsSeparateOpenSpaceFromSolid) {
    const Bsp bsp = parse_ok(test::write_bsp(test::make_box_room(), GetParam()));
    const BspVec3 centre{0, 0, 32};
    for (int hull = 0; hull < 3; ++hull) {
        EXPECT_EQ(point_contents(bsp, hull, centre), bsp_contents::empty) << hull;
        EXPECT_EQ(point_contents(bsp, hull, {0, 0, 1000}), bsp_contents::solid) << hull;
    }
    // 10 units from the x = 128 wall: a point fits, a 16-unit player half-width does not.
    EXPECT_EQ(point_contents(bsp, 0, {118, 0, 32}), bsp_contents::empty);
    EXPECT_EQ(point_contents(bsp, 1, {118, 0, 32}), bsp_contents::solid);
    // 20 units away: the player fits, the 32-unit-wide hull 2 does not.
    EXPECT_EQ(point_contents(bsp, 1, {108, 0, 32}), bsp_contents::empty);
    EXPECT_EQ(point_contents(bsp, 2, {108, 0, 32}), bsp_contents::solid);
    // The crate is model 1: solid inside, empty around it.
    EXPECT_EQ(point_contents(bsp, 0, {80, 80, -48}, 1), bsp_contents::solid);
    EXPECT_EQ(point_contents(bsp, 0, {0, 0, -48}, 1), bsp_contents::empty);
    EXPECT_EQ(point_contents(bsp, 1, {56, 80, -48}, 1), bsp_contents::solid);  // 8 units off
    EXPECT_EQ(point_contents(bsp, 7, centre), bsp_contents::solid);            // no such hull
    EXPECT_EQ(leaf_at(bsp, centre), room::kRoomLeaf);
    EXPECT_EQ(leaf_at(bsp, {0, 0, -48}, 1), room::kCrateLeaf);
}

TEST_P(BspSynth, TracesStopAtFloorsAndWalls) {
    const Bsp bsp = parse_ok(test::write_bsp(test::make_box_room(), GetParam()));
    const BspTrace down = trace_down(bsp, room::kPlayerStart, 1000);
    ASSERT_TRUE(down.hit());
    EXPECT_NEAR(down.end[2], -64, 0.05);  // the floor, less the 1/32 stand-off
    EXPECT_GT(down.end[2], -64);
    EXPECT_EQ(down.plane_normal, (BspVec3{0, 0, 1}));
    EXPECT_FLOAT_EQ(down.plane_dist, -64);
    // The player's box rests 24 units above the floor.
    EXPECT_NEAR(trace_down(bsp, {0, 0, 0}, 1000, 1).end[2], -40, 0.05);
    // Sideways into the crate (model 1) and into a wall (model 0).
    const BspTrace crate = trace_hull(bsp, 0, {0, 80, -48}, {200, 80, -48}, 1);
    EXPECT_NEAR(crate.end[0], 64, 0.05);
    EXPECT_EQ(crate.plane_normal, (BspVec3{-1, 0, 0}));
    const BspTrace wall = trace_hull(bsp, 0, {0, 0, 0}, {-1000, 0, 0});
    EXPECT_NEAR(wall.end[0], -128, 0.05);
    EXPECT_NEAR(wall.fraction, 0.128, 1e-3);
    // Open space the whole way; and a start inside solid.
    const BspTrace open = trace_hull(bsp, 0, {0, 0, 0}, {50, 50, 50});
    EXPECT_FALSE(open.hit());
    EXPECT_EQ(open.end, (BspVec3{50, 50, 50}));
    const BspTrace buried = trace_hull(bsp, 0, {0, 0, 1000}, {0, 0, 2000});
    EXPECT_TRUE(buried.all_solid);
    EXPECT_TRUE(buried.start_solid);
}

TEST_P(BspSynth, PvsOfTheRoomLeaf) {
    SynthBsp synth = test::make_box_room();
    const Bsp bsp = parse_ok(test::write_bsp(synth, GetParam()));
    ASSERT_EQ(pvs_row_bytes(bsp), 1u);
    EXPECT_EQ(decompress_vis(bsp, room::kRoomLeaf), std::vector<uint8_t>{0x01});
    EXPECT_EQ(decompress_vis(bsp, 0), std::vector<uint8_t>{0x00});
    EXPECT_EQ(decompress_vis(bsp, 99), std::vector<uint8_t>{0x00});
    // The crate's leaf has no PVS data: it sees every world leaf (and no padding bits).
    EXPECT_EQ(decompress_vis(bsp, room::kCrateLeaf), std::vector<uint8_t>{0x01});
    // A zero run longer than the row is cut at the row's end, not written past it.
    synth.visibility = {0x00, 0xff};
    EXPECT_EQ(decompress_vis(parse_ok(test::write_bsp(synth, GetParam())), room::kRoomLeaf),
              std::vector<uint8_t>{0x00});
}

TEST_P(BspSynth, MissingTextureBecomesACheckerboardWithAWarning) {
    SynthBsp synth = test::make_box_room();
    synth.textures[1].missing = true;
    const Bsp bsp = parse_ok(test::write_bsp(synth, GetParam()));
    const BspTexture& t = bsp.textures[1];
    EXPECT_TRUE(t.placeholder);
    EXPECT_EQ(t.width, 16u);
    ASSERT_EQ(t.mips[0].pixels.size(), 256u);
    EXPECT_NE(t.mips[0].pixels[0], t.mips[0].pixels[8]);  // squares alternate
    EXPECT_EQ(t.mips[0].pixels[0], t.mips[0].pixels[8 * 16 + 8]);
    EXPECT_EQ(t.mips[3].pixels.size(), 4u);
    EXPECT_TRUE(has_warning(bsp.warnings, "texture 1 has no miptex (offset -1)"));
    EXPECT_FALSE(bsp.textures[0].placeholder);
}

TEST_P(BspSynth, OddTexturesAreWarnedAbout) {
    SynthBsp synth = test::make_box_room();
    synth.textures[0].width = 24;  // not a multiple of 16: kept, levels rounded down
    auto bytes = test::write_bsp(synth, GetParam());
    Bsp bsp = parse_ok(bytes);
    EXPECT_TRUE(has_warning(bsp.warnings, "size 24x16 is not a multiple of 16"));
    EXPECT_EQ(bsp.textures[0].mips[3].width, 3u);
    // A miptex with a header but all-zero level offsets keeps its pixels in a WAD.
    const size_t lump = size_t(read_le32(bytes, 4 + 8 * kTex));
    const size_t miptex = lump + size_t(read_le32(bytes, lump + 4));
    for (int level = 0; level < 4; ++level) put_i32(bytes, miptex + 24 + 4 * level, 0);
    bsp = parse_ok(bytes);
    EXPECT_TRUE(bsp.textures[0].placeholder);
    EXPECT_EQ(bsp.textures[0].name, "wall");
    EXPECT_TRUE(has_warning(bsp.warnings, "'wall' has no pixel data in the map"));
}

TEST_P(BspSynth, EntitiesOfTheBoxRoom) {
    const Bsp bsp = parse_ok(test::write_bsp(test::make_box_room(), GetParam()));
    auto ents = parse_entities(bsp.entities, bsp.name, bsp.entities_offset);
    ASSERT_TRUE(ents);
    ASSERT_EQ(ents->entities.size(), 4u);
    EXPECT_EQ(find_value(ents->entities[0], "sky"), "sky1");
    EXPECT_EQ(find_vec3(ents->entities[1], "origin"), room::kPlayerStart);
    EXPECT_EQ(find_vec3(ents->entities[2], "_color"), (std::array<float, 3>{1, 0.5f, 0.25f}));
    EXPECT_EQ(ents->entities[0].offset, bsp.entities_offset);
}

// ---- .lit files ------------------------------------------------------------------------------

std::vector<uint8_t> lit_file(int32_t version, size_t samples) {
    std::vector<uint8_t> b = {'Q', 'L', 'I', 'T', 0, 0, 0, 0};
    put_i32(b, 4, version);
    for (size_t i = 0; i < samples * 3; ++i) b.push_back(uint8_t(i));
    return b;
}

TEST(BspLit, ColourTriplesForEverySample) {
    auto lit = parse_lit(lit_file(1, 10), "maps/x.lit", 10);
    ASSERT_TRUE(lit) << lit.error().to_string();
    ASSERT_EQ(lit->rgb.size(), 30u);
    EXPECT_EQ(lit->rgb[29], 29);
    EXPECT_TRUE(lit->warnings.empty());
}

TEST(BspLit, SizeMismatchIsIgnoredWithAWarning) {
    auto lit = parse_lit(lit_file(1, 9), "maps/x.lit", 10);
    ASSERT_TRUE(lit);
    EXPECT_TRUE(lit->rgb.empty());
    EXPECT_TRUE(has_warning(lit->warnings, "30 bytes expected"));
    auto ragged = lit_file(1, 10);
    ragged.push_back(0);
    EXPECT_TRUE(parse_lit(ragged, "maps/x.lit", 10)->rgb.empty());
}

TEST(BspLit, BadHeadersAreErrors) {
    auto wrong_version = parse_lit(lit_file(2, 1), "maps/x.lit", 1);
    ASSERT_FALSE(wrong_version);
    EXPECT_EQ(wrong_version.error().offset, 4u);
    EXPECT_NE(wrong_version.error().message.find("version 2"), std::string::npos);
    auto bad_magic = lit_file(1, 1);
    bad_magic[0] = 'X';
    ASSERT_FALSE(parse_lit(bad_magic, "maps/x.lit", 1));
    EXPECT_NE(parse_lit(bad_magic, "maps/x.lit", 1).error().message.find("QLIT"),
              std::string::npos);
    auto truncated = parse_lit(std::vector<uint8_t>{'Q', 'L', 'I'}, "maps/x.lit", 0);
    ASSERT_FALSE(truncated);
    EXPECT_NE(truncated.error().message.find("truncated"), std::string::npos);
}

// ---- Malformed files --------------------------------------------------------------------------

Error parse_error(const std::vector<uint8_t>& bytes) {
    auto bsp = parse_bsp(bytes, "bad.bsp");
    if (bsp) throw std::runtime_error("malformed file parsed without error");
    return bsp.error();
}

void expect_error_in_lump(const Error& e, const std::vector<uint8_t>& bytes, int lump,
                          const std::string& text) {
    EXPECT_EQ(e.file, "bad.bsp");
    EXPECT_NE(e.message.find(text), std::string::npos) << e.to_string();
    const RawSpan span = raw_lump(bytes, lump);
    EXPECT_GE(e.offset, span.offset) << e.to_string();
    EXPECT_LT(e.offset, span.offset + span.length) << e.to_string();
}

TEST_P(BspSynth, HeaderProblemsNameTheirOffset) {
    const auto good = test::write_bsp(test::make_box_room(), GetParam());
    Error e = parse_error(std::vector<uint8_t>(good.begin(), good.begin() + 100));
    EXPECT_EQ(e.offset, 0u);
    EXPECT_NE(e.message.find("truncated header: 100 bytes"), std::string::npos);

    auto bytes = good;
    put_i32(bytes, 0, 30);
    e = parse_error(bytes);
    EXPECT_EQ(e.offset, 0u);
    EXPECT_NE(e.message.find("unsupported BSP version 30"), std::string::npos);

    bytes = good;
    put_i32(bytes, test::synth_bsp_directory_entry(kVerts) + 4, int32_t(good.size()));
    e = parse_error(bytes);
    EXPECT_EQ(e.offset, test::synth_bsp_directory_entry(kVerts));
    EXPECT_NE(e.message.find("lump 3 (vertexes)"), std::string::npos);
    EXPECT_NE(e.message.find("beyond the end of the file"), std::string::npos);

    bytes = good;
    put_i32(bytes, test::synth_bsp_directory_entry(kFaces), -8);
    e = parse_error(bytes);
    EXPECT_EQ(e.offset, test::synth_bsp_directory_entry(kFaces));
    EXPECT_NE(e.message.find("negative offset -8"), std::string::npos);

    bytes = good;
    put_i32(bytes, test::synth_bsp_directory_entry(kVerts) + 4, 13);
    e = parse_error(bytes);
    EXPECT_EQ(e.offset, test::synth_bsp_directory_entry(kVerts) + 4);
    EXPECT_NE(e.message.find("size 13 is not a multiple of its 12-byte record"), std::string::npos);
}

struct BadCase {
    const char* name;
    std::function<void(SynthBsp&)> break_it;
    int lump;          // where the error offset must point
    const char* text;  // what the message must say
};

const BadCase kBadCases[] = {
    {"face plane", [](SynthBsp& b) { b.faces[3].plane = 999; }, kFaces,
     "face 3 plane 999 out of range"},
    {"face texinfo", [](SynthBsp& b) { b.faces[0].texinfo = 3; }, kFaces,
     "face 0 texinfo 3 out of range"},
    {"face edges", [](SynthBsp& b) { b.faces[11].first_surfedge = 46; }, kFaces,
     "face 11 surfedges [46, +4)"},
    {"face edge count", [](SynthBsp& b) { b.faces[2].num_surfedges = 2; }, kFaces,
     "face 2 has 2 edges"},
    {"light offset", [](SynthBsp& b) { b.faces[1].light_offset = int32_t(b.lighting.size()) - 5; },
     kFaces, "lies outside the lighting lump"},
    {"negative light offset", [](SynthBsp& b) { b.faces[1].light_offset = -2; }, kFaces,
     "negative light offset"},
    {"surfedge edge", [](SynthBsp& b) { b.surfedges[5] = 25; }, kSurfedges,
     "surfedge 5 edge 25 out of range"},
    {"reversed surfedge", [](SynthBsp& b) { b.surfedges[5] = -25; }, kSurfedges,
     "surfedge 5 edge 25"},
    {"surfedge INT_MIN", [](SynthBsp& b) { b.surfedges[7] = INT32_MIN; }, kSurfedges,
     "surfedge 7 is INT_MIN"},
    {"edge vertex", [](SynthBsp& b) { b.edges[4][1] = 16; }, kEdges,
     "edge 4 vertex 16 out of range"},
    {"texinfo miptex", [](SynthBsp& b) { b.texinfo[2].miptex = 2; }, kTexinfo,
     "texinfo 2 miptex 2 out of range"},
    {"marksurface face", [](SynthBsp& b) { b.marksurfaces[3] = 12; }, kMarks,
     "marksurface 3 face 12"},
    {"leaf marksurfaces", [](SynthBsp& b) { b.leafs[2].num_marksurfaces = 7; }, kLeafs,
     "leaf 2 marksurfaces [6, +7)"},
    {"leaf contents", [](SynthBsp& b) { b.leafs[1].contents = 3; }, kLeafs,
     "leaf 1 has contents 3"},
    {"leaf vis offset", [](SynthBsp& b) { b.leafs[1].vis_offset = 2; }, kLeafs,
     "leaf 1 visibility offset 2"},
    {"node plane", [](SynthBsp& b) { b.nodes[2].plane = 36; }, kNodes, "node 2 plane 36"},
    {"node child leaf", [](SynthBsp& b) { b.nodes[5].children[1] = -4; }, kNodes,
     "node 5 back child leaf 3"},
    {"node faces", [](SynthBsp& b) { b.nodes[4].first_face = 12; }, kNodes,
     "node 4 faces [12, +1)"},
    {"node cycle", [](SynthBsp& b) { b.nodes[3].children[1] = 1; }, kNodes, "the tree has a cycle"},
    {"clipnode plane", [](SynthBsp& b) { b.clipnodes[1].plane = -1; }, kClip,
     "clipnode 1 plane -1"},
    {"clipnode child", [](SynthBsp& b) { b.clipnodes[0].children[1] = -16; }, kClip,
     "clipnode 0 back child -16 is neither a clipnode"},
    {"clipnode cycle", [](SynthBsp& b) { b.clipnodes[8].children[0] = 6; }, kClip,
     "the tree has a cycle"},
    {"model head node", [](SynthBsp& b) { b.models[1].headnodes[0] = 12; }, kModels,
     "model 1 hull 0 head node 12"},
    {"model head clipnode", [](SynthBsp& b) { b.models[0].headnodes[2] = 24; }, kModels,
     "model 0 hull 2 head clipnode 24"},
    {"model visleafs", [](SynthBsp& b) { b.models[0].visleafs = 3; }, kModels,
     "model 0 visleafs 3 out of range"},
    {"model faces", [](SynthBsp& b) { b.models[1].num_faces = 7; }, kModels,
     "model 1 faces [6, +7)"},
    {"vis run without count",
     [](SynthBsp& b) {
         b.visibility = {0x01, 0x00};
         b.leafs[1].vis_offset = 1;
     },
     kVis, "PVS row of leaf 1 (visibility offset 1"},
    {"vis row overrun", [](SynthBsp& b) { b.visibility = {0x00}; }, kVis,
     "runs past the end of the visibility lump"},
};

TEST_P(BspSynth, EveryBadIndexIsAnErrorNamingItsRecord) {
    for (const BadCase& c : kBadCases) {
        SCOPED_TRACE(c.name);
        SynthBsp synth = test::make_box_room();
        c.break_it(synth);
        const auto bytes = test::write_bsp(synth, GetParam());
        expect_error_in_lump(parse_error(bytes), bytes, c.lump, c.text);
    }
}

TEST_P(BspSynth, ExactOffsetsOfBadFields) {
    SynthBsp synth = test::make_box_room();
    synth.edges[4][1] = 16;
    auto bytes = test::write_bsp(synth, GetParam());
    const size_t edge_size = GetParam() == BspFormat::bsp29 ? 4 : 8;
    EXPECT_EQ(parse_error(bytes).offset,
              raw_lump(bytes, kEdges).offset + 4 * edge_size + edge_size / 2);

    synth = test::make_box_room();
    synth.surfedges[7] = INT32_MIN;
    bytes = test::write_bsp(synth, GetParam());
    EXPECT_EQ(parse_error(bytes).offset, raw_lump(bytes, kSurfedges).offset + 7 * 4);
}

TEST_P(BspSynth, NoModelsIsAnError) {
    SynthBsp synth = test::make_box_room();
    synth.models.clear();
    EXPECT_NE(parse_error(test::write_bsp(synth, GetParam())).message.find("no models"),
              std::string::npos);
}

TEST_P(BspSynth, TooDeepTreesAreRejected) {
    // A chain of 1100 nodes, each with the solid leaf behind it: acyclic but deeper than the
    // traversal bound, so it must be refused rather than walked.
    SynthBsp synth = test::make_box_room();
    synth.nodes.clear();
    for (int64_t i = 0; i < 1100; ++i) {
        SynthBsp::Node n;
        n.children = {i + 1 < 1100 ? i + 1 : -2, -1};
        synth.nodes.push_back(n);
    }
    synth.models[1].headnodes[0] = 0;
    const auto bytes = test::write_bsp(synth, GetParam());
    expect_error_in_lump(parse_error(bytes), bytes, kNodes, "deeper than 1024 levels");
}

TEST_P(BspSynth, LyingMiptexOffsetsAreErrors) {
    const auto good = test::write_bsp(test::make_box_room(), GetParam());
    const size_t lump = raw_lump(good, kTex).offset;
    const size_t lump_len = raw_lump(good, kTex).length;

    auto bytes = good;
    put_i32(bytes, lump + 8, int32_t(lump_len) - 20);  // texture 1's header would overrun
    Error e = parse_error(bytes);
    EXPECT_EQ(e.offset, lump + 8);
    EXPECT_NE(e.message.find("texture 1 miptex offset"), std::string::npos) << e.message;
    EXPECT_NE(e.message.find("lies outside the texture lump"), std::string::npos);

    bytes = good;
    const size_t miptex0 = lump + size_t(read_le32(good, lump + 4));
    put_i32(bytes, miptex0 + 24 + 8, 0x7ffffff0);  // mip level 2
    e = parse_error(bytes);
    EXPECT_EQ(e.offset, miptex0 + 24 + 8);
    EXPECT_NE(e.message.find("'wall' mip level 2"), std::string::npos) << e.message;

    bytes = good;
    put_i32(bytes, lump, 0x7fffffff);
    e = parse_error(bytes);
    EXPECT_EQ(e.offset, lump);
    EXPECT_NE(e.message.find("texture count 2147483647"), std::string::npos);

    // Two entries sharing one big miptex claim its pixels twice, more than the lump holds:
    // refused, or a small file could make the parser allocate without bound.
    SynthBsp synth = test::make_box_room();
    synth.textures[0] = {"big", 64, 64, false};  // 5440 pixel bytes
    bytes = test::write_bsp(synth, GetParam());
    const size_t big_lump = raw_lump(bytes, kTex).offset;
    put_i32(bytes, big_lump + 8, read_le32(bytes, big_lump + 4));
    e = parse_error(bytes);
    EXPECT_NE(e.message.find("texture 'big' mip level 0: textures claim more pixel data"),
              std::string::npos)
        << e.message;
}

TEST_P(BspSynth, PvsValidationAgreesWithABruteForceWalk) {
    // Random compressed data and offsets for 20 world leafs (3-byte rows): the file must parse
    // exactly when every row decodes within the lump, and then decode as the brute force does.
    std::mt19937 rng(1234);
    size_t accepted = 0, refused = 0;
    for (int round = 0; round < 300; ++round) {
        SynthBsp synth = test::make_box_room();
        synth.visibility.resize(4 + rng() % 12);
        for (auto& b : synth.visibility) b = rng() % 3 == 0 ? 0 : uint8_t(rng() % 4);
        for (int i = 0; i < 18; ++i) synth.leafs.push_back(synth.leafs[room::kRoomLeaf]);
        synth.models[0].visleafs = 20;
        bool valid = true;
        for (size_t leaf = 1; leaf < synth.leafs.size(); ++leaf) {
            auto& offset = synth.leafs[leaf].vis_offset;
            offset =
                rng() % 2 ? -1 : int32_t(rng() % (synth.visibility.size() / 2 + 2)) + round % 4;
            if (offset < 0) continue;
            try {
                brute_force_row(synth.visibility, size_t(offset), 3);
            } catch (const std::out_of_range&) {
                valid = false;
            }
        }
        const auto bytes = test::write_bsp(synth, GetParam());
        auto bsp = parse_bsp(bytes, "vis.bsp");
        ASSERT_EQ(bsp.ok(), valid) << (bsp ? "" : bsp.error().to_string());
        if (!valid) {
            ++refused;
            continue;
        }
        ++accepted;
        for (uint32_t leaf = 1; leaf < synth.leafs.size(); ++leaf) {
            const int32_t offset = synth.leafs[leaf].vis_offset;
            const auto row = decompress_vis(*bsp, leaf);
            if (offset < 0) {
                EXPECT_EQ(row, (std::vector<uint8_t>{0xff, 0xff, 0x0f}));  // 20 bits set
            } else {
                EXPECT_EQ(row, brute_force_row(synth.visibility, size_t(offset), 3));
            }
        }
    }
    EXPECT_GT(accepted, 20u) << refused;
    EXPECT_GT(refused, 20u) << accepted;
}

TEST(BspSynthEdge, Bsp29ReadsChildrenUnsigned) {
    // BSP29 children are 16 bits: a value at or above the node count is leaf 65535 - value,
    // which is how -(leaf + 1) looks unsigned. 65533 is leaf 2, 65535 leaf 0.
    SynthBsp synth = test::make_box_room();
    const auto bytes = test::write_bsp(synth, BspFormat::bsp29);
    const size_t node5 = raw_lump(bytes, kNodes).offset + 5 * 24;
    EXPECT_EQ(bytes[node5 + 6] | bytes[node5 + 7] << 8, 65535 - int(room::kRoomLeaf));
    const Bsp bsp = parse_ok(bytes);
    EXPECT_EQ(bsp.nodes[5].children[1], -int32_t(room::kRoomLeaf) - 1);
}

}  // namespace
}  // namespace nq

// Alias models: every LibreQuake model (header fields re-read here from raw bytes), known facts
// of particular models, and synthetic models for every malformed-input class.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>

#include "formats/mdl.h"
#include "support/parse_error_checks.h"
#include "support/raw_bytes.h"
#include "support/synth_mdl.h"
#include "support/test_data.h"

namespace nq {
namespace {

using test::raw_file;
using test::read_le32;
using test::read_lef32;

// Independent little-endian field reads (the test host is little-endian, like the format).

std::string progs(const std::string& file) {
    return test::lq1_dir() + "/progs/" + file;
}

Mdl parse_ok(const std::vector<uint8_t>& bytes, const std::string& name = "test.mdl") {
    auto mdl = parse_mdl(bytes, name);
    if (!mdl) throw std::runtime_error(mdl.error().to_string());
    return std::move(mdl).value();
}

bool has_warning(const Mdl& mdl, const std::string& text) {
    return std::any_of(mdl.warnings.begin(), mdl.warnings.end(),
                       [&](const std::string& w) { return w.find(text) != std::string::npos; });
}

// Models that LibreQuake ships with a "QMEX" editor block after the last frame (found by
// inspecting the files).
const std::set<std::string> kModelsWithQmex = {"boss.mdl",   "eyes.mdl",    "flame.mdl",
                                               "flame0.mdl", "flame2.mdl",  "laser.mdl",
                                               "spike.mdl",  "tarbaby.mdl", "teleport.mdl"};

// ---- every LibreQuake model -----------------------------------------------------------------

void check_header_against_raw(const Mdl& mdl, const std::vector<uint8_t>& raw) {
    const MdlHeader& h = mdl.header;
    EXPECT_EQ(std::string(raw.begin(), raw.begin() + 4), "IDPO");
    EXPECT_EQ(h.version, read_le32(raw, 4));
    for (size_t i = 0; i < 3; ++i) {
        EXPECT_EQ(h.scale[i], read_lef32(raw, 8 + 4 * i));
        EXPECT_EQ(h.scale_origin[i], read_lef32(raw, 20 + 4 * i));
        EXPECT_EQ(h.eye_position[i], read_lef32(raw, 36 + 4 * i));
    }
    EXPECT_EQ(h.bounding_radius, read_lef32(raw, 32));
    EXPECT_EQ(h.num_skins, read_le32(raw, 48));
    EXPECT_EQ(h.skin_width, read_le32(raw, 52));
    EXPECT_EQ(h.skin_height, read_le32(raw, 56));
    EXPECT_EQ(h.num_verts, read_le32(raw, 60));
    EXPECT_EQ(h.num_tris, read_le32(raw, 64));
    EXPECT_EQ(h.num_frames, read_le32(raw, 68));
    EXPECT_EQ(h.sync_type, read_le32(raw, 72));
    EXPECT_EQ(h.flags, read_le32(raw, 76));
    EXPECT_EQ(h.size, read_lef32(raw, 80));
    EXPECT_EQ(mdl.skins.size(), size_t(read_le32(raw, 48)));
    EXPECT_EQ(mdl.tex_coords.size(), size_t(read_le32(raw, 60)));
    EXPECT_EQ(mdl.triangles.size(), size_t(read_le32(raw, 64)));
    EXPECT_EQ(mdl.frames.size(), size_t(read_le32(raw, 68)));
}

void check_structure(const Mdl& mdl) {
    const size_t image = size_t(mdl.header.skin_width) * size_t(mdl.header.skin_height);
    for (const MdlSkin& s : mdl.skins) {
        for (const auto& img : s.images) EXPECT_EQ(img.size(), image);
    }
    for (const MdlTriangle& t : mdl.triangles) {
        for (int32_t v : t.vertices) {
            EXPECT_GE(v, 0);
            EXPECT_LT(v, mdl.header.num_verts);
        }
    }
    for (const MdlFrame& f : mdl.frames) {
        ASSERT_FALSE(f.poses.empty());
        EXPECT_EQ(f.intervals.size(), f.is_group ? f.poses.size() : 0u);
        for (const MdlPose& p : f.poses) {
            EXPECT_EQ(p.vertices.size(), size_t(mdl.header.num_verts));
            EXPECT_FALSE(p.name.empty());
        }
    }
}

void check_bounds_contain_vertices(const Mdl& mdl, const std::string& file) {
    const Bounds bounds = decoded_frame_bounds(mdl);
    size_t outside = 0;
    for (const MdlFrame& f : mdl.frames) {
        for (const MdlPose& p : f.poses) {
            for (const Vec3& v : decoded_positions(mdl.header, p)) {
                if (!bounds.contains(v, 1e-3f)) ++outside;
            }
        }
    }
    EXPECT_EQ(outside, 0u) << file;
}

TEST(MdlReal, EveryModelParses) {
    const auto files = test::lq1_files("progs", ".mdl");
    ASSERT_GE(files.size(), 80u);
    for (const std::string& path : files) {
        SCOPED_TRACE(path);
        const auto raw = raw_file(path);
        auto mdl = parse_mdl(raw, path);
        ASSERT_TRUE(mdl) << mdl.error().to_string();
        check_header_against_raw(*mdl, raw);
        check_structure(*mdl);
        check_bounds_contain_vertices(*mdl, path);
        EXPECT_EQ(mdl->data_end + mdl->trailing_bytes, raw.size());
    }
}

TEST(MdlReal, EditorTrailersAreWarningsNotErrors) {
    for (const std::string& path : test::lq1_files("progs", ".mdl")) {
        SCOPED_TRACE(path);
        const auto raw = raw_file(path);
        const Mdl mdl = parse_ok(raw, path);
        const std::string file = std::filesystem::path(path).filename().string();
        if (kModelsWithQmex.count(file)) {
            ASSERT_GT(mdl.trailing_bytes, 4u);
            EXPECT_EQ(std::string(raw.begin() + mdl.data_end, raw.begin() + mdl.data_end + 4),
                      "QMEX");
            EXPECT_TRUE(has_warning(mdl, "QMEX"));
            EXPECT_TRUE(has_warning(mdl, "offset " + std::to_string(mdl.data_end)));
        } else {
            EXPECT_EQ(mdl.trailing_bytes, 0u);
            EXPECT_EQ(mdl.data_end, raw.size());
            EXPECT_TRUE(mdl.warnings.empty()) << mdl.warnings.front();
        }
    }
}

TEST(MdlReal, PlayerModelFacts) {
    const auto raw = raw_file(progs("player.mdl"));
    const Mdl mdl = parse_ok(raw, "player.mdl");
    // Counts from the header bytes, and the values those bytes hold in LibreQuake.
    EXPECT_EQ(mdl.header.num_verts, 801);
    EXPECT_EQ(mdl.header.num_tris, 1060);
    EXPECT_EQ(mdl.header.num_frames, 143);
    EXPECT_EQ(mdl.header.skin_width, 296);
    EXPECT_EQ(mdl.header.skin_height, 194);
    EXPECT_EQ(mdl.header.flags, 0);
    EXPECT_EQ(mdl.frames.front().poses[0].name, "frame1");
    EXPECT_EQ(mdl.frames.back().poses[0].name, "frame143");

    // Frame 0's first vertex, located by hand: header, one single skin, st verts, triangles,
    // then the frame type, two bbox trivertx and the 16-byte name.
    const size_t frame0 = 84 + 4 + 296 * 194 + 12 * 801 + 16 * 1060;
    ASSERT_EQ(read_le32(raw, frame0), 0);  // a single frame
    const size_t vertex0 = frame0 + 4 + 8 + 16;
    const TriVertex& tv = mdl.frames[0].poses[0].vertices[0];
    for (size_t i = 0; i < 3; ++i) {
        ASSERT_EQ(tv.v[i], raw[vertex0 + i]);
        const float expected =
            read_lef32(raw, 8 + 4 * i) * raw[vertex0 + i] + read_lef32(raw, 20 + 4 * i);
        EXPECT_FLOAT_EQ(decode_vertex(mdl.header, tv)[i], expected);
    }
    EXPECT_EQ(tv.light_normal_index, raw[vertex0 + 3]);
}

TEST(MdlReal, FlameHasAFrameGroup) {
    const Mdl mdl = parse_ok(raw_file(progs("flame.mdl")), "flame.mdl");
    ASSERT_EQ(mdl.frames.size(), 1u);
    const MdlFrame& f = mdl.frames[0];
    ASSERT_TRUE(f.is_group);
    ASSERT_EQ(f.poses.size(), 6u);
    EXPECT_EQ(f.poses[0].name, "flame1");
    EXPECT_EQ(f.poses[5].name, "flame6");
    for (size_t i = 0; i < 6; ++i) EXPECT_FLOAT_EQ(f.intervals[i], 0.1f * float(i + 1));
}

TEST(MdlReal, FlagsByName) {
    const Mdl spike = parse_ok(raw_file(progs("v_spike.mdl")), "v_spike.mdl");
    EXPECT_EQ(spike.header.flags, 136);
    EXPECT_EQ(mdl_flag_names(spike.header.flags), (std::vector<std::string>{"rotate", "tracer3"}));
    const Mdl rocket = parse_ok(raw_file(progs("missile.mdl")), "missile.mdl");
    EXPECT_EQ(mdl_flag_names(rocket.header.flags), (std::vector<std::string>{"rocket"}));
}

// ---- helpers --------------------------------------------------------------------------------

TEST(MdlHelpers, FlagNamesCoverAllBits) {
    EXPECT_TRUE(mdl_flag_names(0).empty());
    EXPECT_EQ(mdl_flag_names(0xff),
              (std::vector<std::string>{"rocket", "grenade", "gib", "rotate", "tracer", "zomgib",
                                        "tracer2", "tracer3"}));
    EXPECT_EQ(mdl_flag_names(0x104), (std::vector<std::string>{"gib", "0x100"}));
    EXPECT_EQ(mdl_flag_names(int32_t(0x80000000u)), (std::vector<std::string>{"0x80000000"}));
}

TEST(MdlHelpers, SyncTypeNames) {
    EXPECT_STREQ(sync_type_name(0), "sync");
    EXPECT_STREQ(sync_type_name(1), "rand");
    EXPECT_STREQ(sync_type_name(7), "unknown");
}

TEST(MdlHelpers, RepairIntervals) {
    std::vector<float> good = {0.1f, 0.2f, 0.5f};
    EXPECT_EQ(repair_intervals(good), 0u);
    EXPECT_EQ(good, (std::vector<float>{0.1f, 0.2f, 0.5f}));
    std::vector<float> bad = {0.0f, 0.3f, 0.2f, NAN, 1.0f};
    EXPECT_EQ(repair_intervals(bad), 3u);
    EXPECT_FLOAT_EQ(bad[0], 0.1f);
    EXPECT_FLOAT_EQ(bad[1], 0.3f);
    EXPECT_FLOAT_EQ(bad[2], 0.4f);
    EXPECT_FLOAT_EQ(bad[3], 0.5f);
    EXPECT_FLOAT_EQ(bad[4], 1.0f);
}

// ---- synthetic models -------------------------------------------------------------------------

TEST(MdlSynthetic, MinimalModel) {
    const test::SynthMdl synth = test::minimal_mdl();
    const Mdl mdl = parse_ok(test::write_mdl(synth));
    EXPECT_TRUE(mdl.warnings.empty());
    EXPECT_EQ(mdl.header.scale, synth.scale);
    EXPECT_EQ(mdl.header.scale_origin, synth.scale_origin);
    EXPECT_EQ(mdl.skins.size(), 1u);
    EXPECT_EQ(mdl.skins[0].images[0], synth.skins[0].images[0]);
    ASSERT_EQ(mdl.tex_coords.size(), 4u);
    EXPECT_EQ(mdl.tex_coords[2].on_seam, 32);
    EXPECT_EQ(mdl.tex_coords[2].s, 8);
    EXPECT_EQ(mdl.triangles[1].vertices, (std::array<int32_t, 3>{0, 2, 3}));
    EXPECT_EQ(mdl.triangles[1].faces_front, 0);
    const MdlPose& pose = mdl.frames[0].poses[0];
    EXPECT_EQ(pose.name, "base");
    EXPECT_EQ(pose.vertices[3].light_normal_index, 161);

    // Decoding: scale (0.5, 0.25, 1), origin (-8, -4, 0); vertex 1 is (40, 20, 30).
    EXPECT_EQ(decode_vertex(mdl.header, pose.vertices[1]), (Vec3{12.0f, 1.0f, 30.0f}));
    const Bounds b = decoded_frame_bounds(mdl);
    EXPECT_EQ(b.min, (Vec3{-3.0f, 1.0f, 30.0f}));
    EXPECT_EQ(b.max, (Vec3{12.0f, 11.0f, 90.0f}));
}

TEST(MdlSynthetic, GroupsAndFlags) {
    const Mdl mdl = parse_ok(test::write_mdl(test::animated_mdl()));
    EXPECT_TRUE(mdl.warnings.empty());
    ASSERT_TRUE(mdl.skins[0].is_group);
    EXPECT_EQ(mdl.skins[0].images.size(), 2u);
    EXPECT_EQ(mdl.skins[0].intervals, (std::vector<float>{0.25f, 0.5f}));
    ASSERT_EQ(mdl.frames.size(), 2u);
    EXPECT_EQ(mdl.frames[0].poses[0].name, "stand1");
    const MdlFrame& run = mdl.frames[1];
    ASSERT_TRUE(run.is_group);
    ASSERT_EQ(run.poses.size(), 3u);
    EXPECT_EQ(run.poses[2].name, "run3");
    EXPECT_EQ(run.poses[2].vertices[0].v[0], 30);
    EXPECT_EQ(mdl_flag_names(mdl.header.flags), (std::vector<std::string>{"rotate", "tracer"}));
    EXPECT_STREQ(sync_type_name(mdl.header.sync_type), "rand");
    // The group box reaches x = 60 -> 0.5 * 60 - 8.
    EXPECT_FLOAT_EQ(decoded_frame_bounds(mdl).max[0], 22.0f);
}

// Offsets in the minimal model (8x4 skin, 4 vertices, 2 triangles), computed from the layout.
constexpr size_t kSkin0 = 84;
constexpr size_t kTexCoords = kSkin0 + 4 + 8 * 4;
constexpr size_t kTriangles = kTexCoords + 4 * 12;
constexpr size_t kFrames = kTriangles + 2 * 16;

Error parse_error(const test::SynthMdl& synth) {
    auto mdl = parse_mdl(test::write_mdl(synth), "bad.mdl");
    if (mdl) throw std::runtime_error("expected an error");
    EXPECT_EQ(mdl.error().file, "bad.mdl");
    return mdl.error();
}

using test::expect_error;

TEST(MdlMalformed, HeaderIdentity) {
    auto bytes = test::write_mdl(test::minimal_mdl());
    bytes.resize(83);
    auto r = parse_mdl(bytes, "bad.mdl");
    ASSERT_FALSE(r);
    expect_error(r.error(), 0, "too small");

    test::SynthMdl m = test::minimal_mdl();
    m.ident = "IDP2";
    expect_error(parse_error(m), 0, "IDPO");
    m = test::minimal_mdl();
    m.version = 7;
    expect_error(parse_error(m), 4, "version 7");
}

TEST(MdlMalformed, NonFiniteScaleAndOrigin) {
    test::SynthMdl m = test::minimal_mdl();
    m.scale[1] = NAN;
    expect_error(parse_error(m), 12, "NaN");
    m = test::minimal_mdl();
    m.scale_origin[2] = INFINITY;
    expect_error(parse_error(m), 28, "infinite");
}

TEST(MdlMalformed, InformationalFloatsOnlyWarn) {
    test::SynthMdl m = test::minimal_mdl();
    m.bounding_radius = NAN;
    m.size = INFINITY;
    const Mdl mdl = parse_ok(test::write_mdl(m));
    EXPECT_EQ(mdl.header.bounding_radius, 0.0f);
    EXPECT_TRUE(has_warning(mdl, "bounding radius"));
    EXPECT_TRUE(has_warning(mdl, "size"));
}

TEST(MdlMalformed, BadSkinDimensions) {
    test::SynthMdl m = test::minimal_mdl();
    m.num_skins = -1;
    expect_error(parse_error(m), 48, "negative skin count");
    m = test::minimal_mdl();
    m.skin_width = 0;
    expect_error(parse_error(m), 52, "skin width");
    m = test::minimal_mdl();
    m.skin_height = -4;
    expect_error(parse_error(m), 56, "skin height");
}

TEST(MdlMalformed, CountsMustBePositive) {
    test::SynthMdl m = test::minimal_mdl();
    m.num_verts = 0;
    expect_error(parse_error(m), 60, "vertex count must be positive");
    m = test::minimal_mdl();
    m.num_tris = -3;
    expect_error(parse_error(m), 64, "triangle count must be positive");
    m = test::minimal_mdl();
    m.num_frames = 0;
    expect_error(parse_error(m), 68, "frame count must be positive");
}

TEST(MdlMalformed, CountsLargerThanTheFile) {
    test::SynthMdl m = test::minimal_mdl();
    m.num_verts = 0x7fffffff;
    expect_error(parse_error(m), 60, "cannot fit");
    m = test::minimal_mdl();
    m.num_tris = 100000;
    expect_error(parse_error(m), 64, "cannot fit");
    m = test::minimal_mdl();
    m.num_frames = 50;
    expect_error(parse_error(m), 68, "cannot fit");
}

TEST(MdlMalformed, SkinCountLargerThanTheFile) {
    test::SynthMdl m = test::minimal_mdl();
    m.num_skins = 1000;
    expect_error(parse_error(m), kSkin0, "skins");
    m = test::minimal_mdl();
    m.skin_width = 0x7fffffff;
    m.skin_height = 0x7fffffff;
    expect_error(parse_error(m), kSkin0, "exceeds");
}

TEST(MdlMalformed, BadSkinTypeAndGroups) {
    test::SynthMdl m = test::minimal_mdl();
    m.skins[0].type = 5;
    expect_error(parse_error(m), kSkin0, "skin 0 has unknown type 5");
    m = test::animated_mdl();
    m.skins[0].group_count = 0;
    expect_error(parse_error(m), kSkin0 + 4, "skin 0 group count must be positive");
    m = test::animated_mdl();
    m.skins[0].group_count = 40;
    expect_error(parse_error(m), kSkin0 + 8, "skin 0 group");
}

TEST(MdlMalformed, TriangleIndexOutOfRange) {
    test::SynthMdl m = test::minimal_mdl();
    m.triangles[1].vertices[2] = 4;  // == num_verts
    const size_t field = kTriangles + 16 + 4 + 2 * 4;
    expect_error(parse_error(m), field, "triangle 1 vertex 2 index 4 is out of range");
    m.triangles[1].vertices[2] = 0;
    m.triangles[0].vertices[0] = -1;
    expect_error(parse_error(m), kTriangles + 4, "index -1");
}

TEST(MdlMalformed, BadFrameTypeAndGroups) {
    test::SynthMdl m = test::minimal_mdl();
    m.frames[0].type = 2;
    expect_error(parse_error(m), kFrames, "frame 0 has unknown type 2");

    m = test::animated_mdl();
    const size_t skin_bytes = 4 + 4 + 2 * 4 + 2 * 32;  // type, count, 2 intervals, 2 images
    const size_t frame1 = 84 + skin_bytes + 4 * 12 + 2 * 16 + (4 + 24 + 4 * 4);
    m.frames[1].group_count = 0;
    expect_error(parse_error(m), frame1 + 4, "frame 1 group count must be positive");
    m.frames[1].group_count = 1000;
    expect_error(parse_error(m), frame1 + 16, "frame 1 group");
}

TEST(MdlMalformed, EveryTruncationIsAnError) {
    const auto full = test::write_mdl(test::animated_mdl());
    for (size_t n = 0; n < full.size(); ++n) {
        std::vector<uint8_t> cut(full.begin(), full.begin() + n);
        auto mdl = parse_mdl(cut, "cut.mdl");
        ASSERT_FALSE(mdl) << "prefix of " << n << " bytes parsed";
        EXPECT_LE(mdl.error().offset, n) << mdl.error().to_string();
        EXPECT_FALSE(mdl.error().message.empty());
    }
}

TEST(MdlWarnings, OddButHarmlessContent) {
    test::SynthMdl m = test::minimal_mdl();
    m.skin_width = 6;  // not a multiple of 4
    for (auto& image : m.skins[0].images) image.resize(6 * 4);
    m.tex_coords[1].s = 7;
    m.tex_coords[2].s = 99;  // outside the 6-wide skin
    m.tex_coords[3].t = -1;
    m.sync_type = 3;
    m.frames[0].poses[0].vertices[0].normal = 200;
    const Mdl mdl = parse_ok(test::write_mdl(m));
    EXPECT_TRUE(has_warning(mdl, "not a multiple of 4"));
    EXPECT_TRUE(has_warning(mdl, "3 texture coordinate(s) lie outside the 6x4 skin"));
    EXPECT_TRUE(has_warning(mdl, "unknown sync type 3"));
    EXPECT_TRUE(has_warning(mdl, "1 light normal index"));
    EXPECT_EQ(mdl.frames[0].poses[0].vertices[0].light_normal_index, kNumVertexNormals - 1);
}

TEST(MdlWarnings, BadIntervalsAreRepaired) {
    test::SynthMdl m = test::animated_mdl();
    m.frames[1].intervals = {0.2f, 0.1f, -1.0f};
    m.skins[0].intervals = {NAN, 0.5f};
    const Mdl mdl = parse_ok(test::write_mdl(m));
    EXPECT_TRUE(has_warning(mdl, "frame 1: 2 interval(s)"));
    EXPECT_TRUE(has_warning(mdl, "skin 0: 1 interval(s) at offset 92"));
    EXPECT_FLOAT_EQ(mdl.frames[1].intervals[1], 0.3f);
    EXPECT_FLOAT_EQ(mdl.skins[0].intervals[0], 0.1f);
}

TEST(MdlWarnings, TrailingDataAndMissingSkins) {
    test::SynthMdl m = test::minimal_mdl();
    m.trailing = {'Q', 'M', 'E', 'X', 1, 2, 3};
    Mdl mdl = parse_ok(test::write_mdl(m));
    EXPECT_EQ(mdl.trailing_bytes, 7u);
    EXPECT_TRUE(has_warning(mdl, "7 trailing byte(s)"));
    EXPECT_TRUE(has_warning(mdl, "QMEX"));

    m = test::minimal_mdl();
    m.trailing = {1};
    m.skins.clear();
    mdl = parse_ok(test::write_mdl(m));
    EXPECT_TRUE(has_warning(mdl, "no skins"));
    EXPECT_TRUE(has_warning(mdl, "1 trailing byte(s)"));
    EXPECT_FALSE(has_warning(mdl, "QMEX"));
}

TEST(MdlWarnings, OverTheOriginalEngineLimits) {
    test::SynthMdl m = test::minimal_mdl();
    const size_t verts = 1100;
    m.tex_coords.resize(verts);
    m.frames[0].poses[0].vertices.resize(verts);
    const Mdl mdl = parse_ok(test::write_mdl(m));
    EXPECT_TRUE(has_warning(mdl, "1100 vertices exceed the original engine's limit of 1024"));
}

}  // namespace
}  // namespace nq

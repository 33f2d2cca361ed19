// Sprites: every LibreQuake sprite (header and frames re-read here from raw bytes) and
// synthetic sprites for every malformed-input class.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>

#include "formats/spr.h"
#include "support/parse_error_checks.h"
#include "support/raw_bytes.h"
#include "support/synth_spr.h"
#include "support/test_data.h"

namespace nq {
namespace {

using test::raw_file;
using test::read_le32;
using test::read_lef32;

Spr parse_ok(const std::vector<uint8_t>& bytes, const std::string& name = "test.spr") {
    auto spr = parse_spr(bytes, name);
    if (!spr) throw std::runtime_error(spr.error().to_string());
    return std::move(spr).value();
}

bool has_warning(const Spr& spr, const std::string& text) {
    return std::any_of(spr.warnings.begin(), spr.warnings.end(),
                       [&](const std::string& w) { return w.find(text) != std::string::npos; });
}

// ---- LibreQuake sprites -----------------------------------------------------------------------

TEST(SprReal, EverySpriteMatchesRawBytes) {
    const auto files = test::lq1_files("progs", ".spr");
    ASSERT_GE(files.size(), 4u);
    for (const std::string& path : files) {
        SCOPED_TRACE(path);
        const auto raw = raw_file(path);
        auto spr = parse_spr(raw, path);
        ASSERT_TRUE(spr) << spr.error().to_string();
        const SprHeader& h = spr->header;
        EXPECT_EQ(std::string(raw.begin(), raw.begin() + 4), "IDSP");
        EXPECT_EQ(h.version, read_le32(raw, 4));
        EXPECT_EQ(h.type, read_le32(raw, 8));
        EXPECT_EQ(h.bounding_radius, read_lef32(raw, 12));
        EXPECT_EQ(h.max_width, read_le32(raw, 16));
        EXPECT_EQ(h.max_height, read_le32(raw, 20));
        EXPECT_EQ(h.num_frames, read_le32(raw, 24));
        EXPECT_EQ(h.beam_length, read_lef32(raw, 28));
        EXPECT_EQ(h.sync_type, read_le32(raw, 32));
        EXPECT_TRUE(spr->warnings.empty()) << spr->warnings.front();
        EXPECT_EQ(spr->trailing_bytes, 0u);

        // LibreQuake's sprites hold single frames only: walk them independently.
        size_t at = 36;
        ASSERT_EQ(spr->frames.size(), size_t(h.num_frames));
        for (const SprFrame& f : spr->frames) {
            ASSERT_EQ(read_le32(raw, at), 0);
            ASSERT_FALSE(f.is_group);
            const SprPicture& p = f.pictures[0];
            EXPECT_EQ(p.origin_x, read_le32(raw, at + 4));
            EXPECT_EQ(p.origin_y, read_le32(raw, at + 8));
            EXPECT_EQ(p.width, read_le32(raw, at + 12));
            EXPECT_EQ(p.height, read_le32(raw, at + 16));
            EXPECT_LE(p.width, h.max_width);
            EXPECT_TRUE(std::equal(p.pixels.begin(), p.pixels.end(), raw.begin() + at + 20));
            at += 20 + p.pixels.size();
        }
        EXPECT_EQ(at, raw.size());
    }
}

TEST(SprReal, ExplosionFacts) {
    const Spr spr = parse_ok(raw_file(test::lq1_dir() + "/progs/s_explod.spr"), "s_explod.spr");
    EXPECT_STREQ(sprite_type_name(spr.header.type), "vp_parallel");
    ASSERT_EQ(spr.frames.size(), 6u);
    for (const SprFrame& f : spr.frames) {
        EXPECT_EQ(f.pictures[0].width, 64);
        EXPECT_EQ(f.pictures[0].height, 64);
        EXPECT_EQ(f.pictures[0].origin_x, -32);
        EXPECT_EQ(f.pictures[0].origin_y, 32);
    }
}

// ---- synthetic sprites ------------------------------------------------------------------------

TEST(SprSynthetic, MinimalAndAnimated) {
    Spr spr = parse_ok(test::write_spr(test::minimal_spr()));
    EXPECT_TRUE(spr.warnings.empty());
    ASSERT_EQ(spr.frames.size(), 1u);
    EXPECT_EQ(spr.frames[0].pictures[0].pixels, test::synth_picture(4, 4, 1).pixels);

    spr = parse_ok(test::write_spr(test::animated_spr()));
    EXPECT_TRUE(spr.warnings.empty());
    EXPECT_STREQ(sprite_type_name(spr.header.type), "oriented");
    ASSERT_EQ(spr.frames.size(), 2u);
    const SprFrame& group = spr.frames[1];
    ASSERT_TRUE(group.is_group);
    EXPECT_EQ(group.intervals, (std::vector<float>{0.1f, 0.25f}));
    ASSERT_EQ(group.pictures.size(), 2u);
    EXPECT_EQ(group.pictures[1].width, 2);
    EXPECT_EQ(group.pictures[1].height, 4);
    EXPECT_EQ(group.pictures[1].origin_x, -1);
    EXPECT_EQ(group.pictures[1].pixels[7], 47);
}

TEST(SprSynthetic, TypeNames) {
    EXPECT_STREQ(sprite_type_name(0), "vp_parallel_upright");
    EXPECT_STREQ(sprite_type_name(1), "facing_upright");
    EXPECT_STREQ(sprite_type_name(4), "vp_parallel_oriented");
    EXPECT_STREQ(sprite_type_name(5), "unknown");
}

constexpr size_t kFrame0 = 36;
// In animated_spr: frame 0 (4x4 single) takes 4 + 16 + 16 bytes.
constexpr size_t kFrame1 = kFrame0 + 36;

Error parse_error(const test::SynthSpr& synth) {
    auto spr = parse_spr(test::write_spr(synth), "bad.spr");
    if (spr) throw std::runtime_error("expected an error");
    EXPECT_EQ(spr.error().file, "bad.spr");
    return spr.error();
}

using test::expect_error;

TEST(SprMalformed, HeaderIdentity) {
    auto bytes = test::write_spr(test::minimal_spr());
    bytes.resize(35);
    auto r = parse_spr(bytes, "bad.spr");
    ASSERT_FALSE(r);
    expect_error(r.error(), 0, "too small");

    test::SynthSpr s = test::minimal_spr();
    s.ident = "IDPO";
    expect_error(parse_error(s), 0, "IDSP");
    s = test::minimal_spr();
    s.version = 2;  // Half-Life's sprites
    expect_error(parse_error(s), 4, "version 2");
    s = test::minimal_spr();
    s.type = 5;
    expect_error(parse_error(s), 8, "unknown sprite type 5");
}

TEST(SprMalformed, FrameCount) {
    test::SynthSpr s = test::minimal_spr();
    s.num_frames = 0;
    expect_error(parse_error(s), 24, "frame count must be positive");
    s.num_frames = -7;
    expect_error(parse_error(s), 24, "-7");
    s.num_frames = 3;  // 36 bytes of frames cannot hold 3 frames of >= 20 bytes
    expect_error(parse_error(s), 24, "cannot fit");
    s.num_frames = 2;  // with 4 more bytes this fits the size check, but frame 1 is cut short
    s.trailing = {0, 0, 0, 0};
    expect_error(parse_error(s), kFrame0 + 36 + 4, "unexpected end");
}

TEST(SprMalformed, FrameTypeAndGroupCount) {
    test::SynthSpr s = test::animated_spr();
    s.frames[0].type = 9;
    expect_error(parse_error(s), kFrame0, "frame 0 has unknown type 9");
    s = test::animated_spr();
    s.frames[1].group_count = 0;
    expect_error(parse_error(s), kFrame1 + 4, "frame 1 group count must be positive");
    s.frames[1].group_count = 1 << 20;
    expect_error(parse_error(s), kFrame1 + 8, "frame 1 group");
}

TEST(SprMalformed, PictureSizes) {
    test::SynthSpr s = test::minimal_spr();
    s.frames[0].pictures[0].width = 0;
    expect_error(parse_error(s), kFrame0 + 12, "frame 0 width must be positive");
    s = test::minimal_spr();
    s.frames[0].pictures[0].height = -4;
    expect_error(parse_error(s), kFrame0 + 16, "height must be positive");
    s = test::minimal_spr();
    s.frames[0].pictures[0].width = 0x10000;
    s.frames[0].pictures[0].height = 0x10000;
    expect_error(parse_error(s), kFrame0 + 20, "frame 0 pixels (65536x65536)");
    s = test::animated_spr();
    s.frames[1].pictures[1].height = 5;  // one row more than stored
    expect_error(parse_error(s), kFrame1 + 8 + 8 + (16 + 8) + 16, "frame 1 picture 1 pixels");
}

TEST(SprMalformed, EveryTruncationIsAnError) {
    const auto full = test::write_spr(test::animated_spr());
    for (size_t n = 0; n < full.size(); ++n) {
        auto spr = parse_spr(std::vector<uint8_t>(full.begin(), full.begin() + n), "cut.spr");
        ASSERT_FALSE(spr) << "prefix of " << n << " bytes parsed";
        EXPECT_LE(spr.error().offset, n) << spr.error().to_string();
    }
}

TEST(SprWarnings, OddButHarmlessContent) {
    test::SynthSpr s = test::animated_spr();
    s.frames[1].intervals = {0.3f, 0.2f};
    s.max_width = 3;  // the 4-wide pictures exceed it
    s.sync_type = 4;
    s.bounding_radius = NAN;
    s.trailing = {0, 0, 0};
    const Spr spr = parse_ok(test::write_spr(s));
    EXPECT_TRUE(has_warning(spr, "frame 1: 1 interval(s)"));
    EXPECT_FLOAT_EQ(spr.frames[1].intervals[1], 0.4f);
    EXPECT_TRUE(has_warning(spr, "2 picture(s) larger than the header's maximum 3x4"));
    EXPECT_TRUE(has_warning(spr, "unknown sync type 4"));
    EXPECT_TRUE(has_warning(spr, "bounding radius"));
    EXPECT_TRUE(has_warning(spr, "3 trailing byte(s)"));
    EXPECT_EQ(spr.trailing_bytes, 3u);
}

}  // namespace
}  // namespace nq

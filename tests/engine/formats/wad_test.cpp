// WAD2 directories and the pictures in them (qpic, raw CONCHARS), against LibreQuake's
// gfx.wad (directory re-read independently here) and synthetic archives of every bad kind.
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <iterator>

#include "formats/lmp.h"
#include "formats/palette.h"
#include "formats/wad.h"
#include "support/parse_error_checks.h"
#include "support/raw_bytes.h"
#include "support/synth_wad.h"
#include "support/test_data.h"

namespace nq {
namespace {

using test::raw_file;
using test::read_le32;

std::vector<uint8_t> gfx_wad_bytes() {
    return raw_file(test::lq1_dir() + "/gfx.wad");
}

Wad parse_ok(const std::vector<uint8_t>& bytes, const std::string& name = "test.wad") {
    auto wad = parse_wad(bytes, name);
    if (!wad) throw std::runtime_error(wad.error().to_string());
    return std::move(wad).value();
}

bool has_warning(const std::vector<std::string>& warnings, const std::string& text) {
    for (const auto& w : warnings) {
        if (w.find(text) != std::string::npos) return true;
    }
    return false;
}

// ---- LibreQuake gfx.wad -------------------------------------------------------------------

TEST(WadReal, DirectoryMatchesRawEntries) {
    const auto raw = gfx_wad_bytes();
    ASSERT_EQ(std::string(raw.begin(), raw.begin() + 4), "WAD2");
    const int32_t num_lumps = read_le32(raw, 4);
    const int32_t dir = read_le32(raw, 8);
    const Wad wad = parse_ok(raw, "gfx.wad");
    ASSERT_EQ(wad.lumps.size(), size_t(num_lumps));
    for (size_t i = 0; i < wad.lumps.size(); ++i) {
        const size_t e = size_t(dir) + 32 * i;
        const WadLump& lump = wad.lumps[i];
        EXPECT_EQ(lump.file_offset, uint32_t(read_le32(raw, e)));
        EXPECT_EQ(lump.disk_size, uint32_t(read_le32(raw, e + 4)));
        EXPECT_EQ(lump.size, uint32_t(read_le32(raw, e + 8)));
        EXPECT_EQ(lump.type, raw[e + 12]);
        EXPECT_EQ(lump.compression, raw[e + 13]);
        const char* name = reinterpret_cast<const char*>(&raw[e + 16]);
        EXPECT_EQ(lump.name, std::string(name, strnlen(name, 16)));
    }
    EXPECT_TRUE(wad.warnings.empty()) << wad.warnings.front();
}

TEST(WadReal, ConcharsIsRaw128x128) {
    const auto raw = gfx_wad_bytes();
    const Wad wad = parse_ok(raw, "gfx.wad");
    const WadLump* lump = wad.find("conchars");  // stored upper-case
    ASSERT_NE(lump, nullptr);
    EXPECT_EQ(lump->size, 128u * 128u);
    auto pic = parse_wad_pic(wad, *lump);
    ASSERT_TRUE(pic) << pic.error().to_string();
    EXPECT_EQ(pic->width, 128);
    EXPECT_EQ(pic->height, 128);
    ASSERT_EQ(pic->pixels.size(), 128u * 128u);
    EXPECT_TRUE(
        std::equal(pic->pixels.begin(), pic->pixels.end(), raw.begin() + lump->file_offset));
}

TEST(WadReal, StatusBarPictures) {
    const auto raw = gfx_wad_bytes();
    const Wad wad = parse_ok(raw, "gfx.wad");
    struct Expected {
        const char* name;
        int w, h;
    };
    for (const Expected& e :
         {Expected{"num_0", 24, 24}, Expected{"NUM_MINUS", 24, 24}, Expected{"sbar", 320, 24},
          Expected{"ibar", 320, 24}, Expected{"face1", 24, 24}, Expected{"sb_sigil1", 8, 16}}) {
        const WadLump* lump = wad.find(e.name);
        ASSERT_NE(lump, nullptr) << e.name;
        auto pic = parse_wad_pic(wad, *lump);
        ASSERT_TRUE(pic) << pic.error().to_string();
        EXPECT_EQ(pic->width, e.w) << e.name;
        EXPECT_EQ(pic->height, e.h) << e.name;
        EXPECT_EQ(pic->width, read_le32(raw, lump->file_offset)) << e.name;
        EXPECT_EQ(pic->height, read_le32(raw, lump->file_offset + 4)) << e.name;
        EXPECT_EQ(pic->at(e.w - 1, e.h - 1), raw[lump->file_offset + 8 + e.w * e.h - 1]);
    }
}

TEST(WadReal, EveryQpicFillsItsLump) {
    const Wad wad = parse_ok(gfx_wad_bytes(), "gfx.wad");
    size_t pictures = 0;
    for (const WadLump& lump : wad.lumps) {
        if (lump.type != uint8_t(WadLumpType::QPic)) continue;
        auto pic = parse_wad_pic(wad, lump);
        ASSERT_TRUE(pic) << pic.error().to_string();
        EXPECT_EQ(8u + pic->pixels.size(), lump.size) << lump.name;
        EXPECT_TRUE(pic->warnings.empty()) << lump.name;
        ++pictures;
    }
    EXPECT_GT(pictures, 100u);
}

TEST(WadReal, LookupIgnoresCase) {
    const Wad wad = parse_ok(gfx_wad_bytes(), "gfx.wad");
    const WadLump* a = wad.find("NuM_0");
    ASSERT_NE(a, nullptr);
    EXPECT_EQ(a, wad.find("num_0"));
    EXPECT_EQ(a->name, "NUM_0");
    EXPECT_EQ(wad.find("num_00"), nullptr);
    EXPECT_EQ(wad.find(""), nullptr);
}

// ---- synthetic archives ---------------------------------------------------------------------

TEST(WadSynthetic, SampleRoundTrips) {
    const test::SynthWad synth = test::sample_wad();
    const Wad wad = parse_ok(test::write_wad(synth));
    ASSERT_EQ(wad.lumps.size(), 4u);
    EXPECT_TRUE(wad.warnings.empty());
    EXPECT_EQ(wad.lumps[3].file_offset, test::synth_wad_lump_offset(synth, 3));

    auto face = parse_wad_pic(wad, *wad.find("FACE1"));
    ASSERT_TRUE(face) << face.error().to_string();
    EXPECT_EQ(face->width, 3);
    EXPECT_EQ(face->height, 2);
    EXPECT_EQ(face->pixels, (std::vector<uint8_t>{1, 2, 3, 4, 5, 6}));

    const WadLump* palette = wad.find("palette");
    ASSERT_NE(palette, nullptr);
    auto bytes = wad.lump_bytes(*palette);
    ASSERT_TRUE(bytes);
    auto pal = parse_palette(*bytes, "palette lump");
    ASSERT_TRUE(pal) << pal.error().to_string();
    EXPECT_EQ(pal->colors[10], (Rgb{10, 245, 5}));
}

TEST(WadSynthetic, ConcharsByTypeE) {
    test::SynthWad synth;
    synth.lumps.push_back({"font", 0x45, 0, test::gradient_pixels(128 * 128, 3), {}, {}, {}});
    const Wad wad = parse_ok(test::write_wad(synth));
    auto pic = parse_wad_pic(wad, wad.lumps[0]);
    ASSERT_TRUE(pic) << pic.error().to_string();
    EXPECT_EQ(pic->width, 128);
    EXPECT_EQ(pic->at(1, 0), 4);
}

Error parse_error(const std::vector<uint8_t>& bytes) {
    auto wad = parse_wad(bytes, "bad.wad");
    if (wad) throw std::runtime_error("expected an error");
    EXPECT_EQ(wad.error().file, "bad.wad");
    return wad.error();
}

using test::expect_error;

TEST(WadMalformed, TooSmallForHeader) {
    auto bytes = test::write_wad(test::sample_wad());
    bytes.resize(11);
    expect_error(parse_error(bytes), 0, "too small");
}

TEST(WadMalformed, WrongIdentifier) {
    test::SynthWad synth = test::sample_wad();
    synth.ident = "WAD3";
    expect_error(parse_error(test::write_wad(synth)), 0, "WAD2");
}

TEST(WadMalformed, NegativeLumpCount) {
    test::SynthWad synth = test::sample_wad();
    synth.num_lumps = -1;
    expect_error(parse_error(test::write_wad(synth)), 4, "negative lump count");
}

TEST(WadMalformed, DirectoryOffsetPastEnd) {
    test::SynthWad synth = test::sample_wad();
    synth.dir_offset = 1 << 24;
    expect_error(parse_error(test::write_wad(synth)), 8, "past the end");
    synth.dir_offset = -5;
    expect_error(parse_error(test::write_wad(synth)), 8, "negative");
}

TEST(WadMalformed, LumpCountLargerThanDirectory) {
    test::SynthWad synth = test::sample_wad();
    synth.num_lumps = 5;  // 4 entries present
    const size_t dir = test::synth_wad_lump_offset(synth, 4);
    expect_error(parse_error(test::write_wad(synth)), dir, "WAD directory");
    synth.num_lumps = 0x7fffffff;
    expect_error(parse_error(test::write_wad(synth)), dir, "exceeds");
}

TEST(WadMalformed, LumpOutsideFile) {
    test::SynthWad synth = test::sample_wad();
    synth.lumps[2].disk_size = 1 << 20;
    const size_t entry = test::synth_wad_lump_offset(synth, 4) + 2 * 32;
    expect_error(parse_error(test::write_wad(synth)), entry, "'Palette'");
    synth.lumps[2].disk_size.reset();
    synth.lumps[2].file_offset = 0x7ffffff0;
    expect_error(parse_error(test::write_wad(synth)), entry, "outside the file");
}

TEST(WadMalformed, NegativeLumpFields) {
    test::SynthWad synth = test::sample_wad();
    const size_t entry = test::synth_wad_lump_offset(synth, 4) + 32;
    synth.lumps[1].size = -2;
    expect_error(parse_error(test::write_wad(synth)), entry + 8, "lump 1 size is negative");
    synth.lumps[1].size.reset();
    synth.lumps[1].file_offset = -2;
    expect_error(parse_error(test::write_wad(synth)), entry, "file offset is negative");
}

TEST(WadMalformed, CompressedLumpFailsOnlyWhenRead) {
    test::SynthWad synth = test::sample_wad();
    synth.lumps[3].compression = 1;
    const Wad wad = parse_ok(test::write_wad(synth));
    EXPECT_TRUE(has_warning(wad.warnings, "compressed"));
    const WadLump& lump = *wad.find("face1");
    auto bytes = wad.lump_bytes(lump);
    ASSERT_FALSE(bytes);
    expect_error(bytes.error(), test::synth_wad_lump_offset(synth, 3), "compressed");
    auto pic = parse_wad_pic(wad, lump);
    ASSERT_FALSE(pic);
    EXPECT_NE(pic.error().message.find("face1"), std::string::npos);
    // The other lumps are still readable.
    EXPECT_TRUE(parse_wad_pic(wad, *wad.find("num_0")));
}

TEST(WadMalformed, OddButHarmlessEntriesWarn) {
    test::SynthWad synth = test::sample_wad();
    synth.lumps.push_back({"num_0", 0x42, 0, test::write_qpic(1, 1, {9}), {}, {}, {}});
    synth.lumps.push_back({"", 0x51, 0, {1, 2}, {}, {}, {}});
    synth.lumps[3].size = 99;
    const Wad wad = parse_ok(test::write_wad(synth));
    EXPECT_TRUE(has_warning(wad.warnings, "repeats an earlier name"));
    EXPECT_TRUE(has_warning(wad.warnings, "unknown type 0x51"));
    EXPECT_TRUE(has_warning(wad.warnings, "empty name"));
    EXPECT_TRUE(has_warning(wad.warnings, "size 99 differs"));
    EXPECT_EQ(parse_wad_pic(wad, *wad.find("NUM_0"))->width, 24);  // the first one wins
}

TEST(WadMalformed, TruncatedPictureInsideLump) {
    test::SynthWad synth = test::sample_wad();
    synth.lumps[3].data = test::write_qpic(300, 300, {1, 2, 3});
    const Wad wad = parse_ok(test::write_wad(synth));
    auto pic = parse_wad_pic(wad, *wad.find("face1"));
    ASSERT_FALSE(pic);
    // The offset is absolute in the WAD: just past the lump's 8-byte picture header.
    expect_error(pic.error(), test::synth_wad_lump_offset(synth, 3) + 8, "face1");
    EXPECT_NE(pic.error().message.find("300x300"), std::string::npos);
}

TEST(WadMalformed, NonPictureLumpIsNotAPicture) {
    const Wad wad = parse_ok(test::write_wad(test::sample_wad()));
    auto pic = parse_wad_pic(wad, *wad.find("palette"));
    ASSERT_FALSE(pic);
    EXPECT_NE(pic.error().message.find("not a picture"), std::string::npos);
}

// ---- loose qpic / conchars ------------------------------------------------------------------

TEST(Qpic, ParsesAndWarnsOnTrailingBytes) {
    auto bytes = test::write_qpic(5, 3, test::gradient_pixels(15, 100));
    auto pic = parse_qpic(bytes, "pic.lmp");
    ASSERT_TRUE(pic) << pic.error().to_string();
    EXPECT_EQ(pic->at(4, 2), 114);
    EXPECT_TRUE(pic->warnings.empty());
    bytes.push_back(0);
    pic = parse_qpic(bytes, "pic.lmp");
    ASSERT_TRUE(pic);
    EXPECT_TRUE(has_warning(pic->warnings, "1 trailing byte"));
}

TEST(Qpic, MalformedSizes) {
    auto e = parse_qpic(test::write_qpic(-4, 3, {}), "pic.lmp");
    ASSERT_FALSE(e);
    expect_error(e.error(), 0, "width must be positive, is -4");
    e = parse_qpic(test::write_qpic(4, -3, {}), "pic.lmp");
    ASSERT_FALSE(e);
    expect_error(e.error(), 4, "height must be positive, is -3");
    e = parse_qpic(test::write_qpic(0x7fffffff, 0x7fffffff, {1}), "pic.lmp");
    ASSERT_FALSE(e);
    expect_error(e.error(), 8, "picture pixels");
    e = parse_qpic(std::vector<uint8_t>{1, 0, 0}, "pic.lmp");
    ASSERT_FALSE(e);
    expect_error(e.error(), 0, "unexpected end");
}

TEST(Qpic, EmptyPictureIsAnError) {
    // No Quake picture is empty, and a 0 x 2^31 one would make row loops spin for nothing.
    auto pic = parse_qpic(test::write_qpic(0, 0x7fffffff, {}), "pic.lmp");
    ASSERT_FALSE(pic);
    expect_error(pic.error(), 0, "width must be positive, is 0");
}

TEST(Conchars, ShortFontIsAnError) {
    auto e = parse_conchars(test::gradient_pixels(1000, 0), "conchars", 40);
    ASSERT_FALSE(e);
    expect_error(e.error(), 40, "128x128");
}

}  // namespace
}  // namespace nq

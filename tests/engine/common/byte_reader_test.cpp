#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "common/byte_reader.h"
#include "common/result.h"

namespace nq {
namespace {

std::vector<uint8_t> bytes(std::initializer_list<int> v) {
    std::vector<uint8_t> out;
    for (int b : v) out.push_back(static_cast<uint8_t>(b));
    return out;
}

TEST(ByteReader, ReadsLittleEndianIntegers) {
    auto data = bytes({0x34, 0x12, 0x78, 0x56, 0x34, 0x12, 0xff, 0xff, 0xff, 0xff});
    ByteReader r(data, "t.bin");
    EXPECT_EQ(r.u16(), 0x1234);
    EXPECT_EQ(r.u32(), 0x12345678u);
    EXPECT_EQ(r.i32(), -1);
    EXPECT_TRUE(r.at_end());
}

TEST(ByteReader, ReadsIeeeFloats) {
    // 1.5f is 0x3fc00000; stored little-endian.
    auto data = bytes({0x00, 0x00, 0xc0, 0x3f});
    ByteReader r(data, "t.bin");
    EXPECT_FLOAT_EQ(r.f32(), 1.5f);
}

TEST(ByteReader, RejectsNonFiniteFloatWhereAsked) {
    auto data = bytes({0x00, 0x00, 0xc0, 0x7f});  // quiet NaN
    ByteReader r(data, "t.bin");
    try {
        r.f32_finite();
        FAIL() << "NaN accepted";
    } catch (const FormatError& e) {
        EXPECT_EQ(e.error().offset, 0u);
        EXPECT_NE(e.error().message.find("NaN"), std::string::npos);
    }
}

TEST(ByteReader, ReadPastEndNamesFileAndAbsoluteOffset) {
    auto data = bytes({1, 2, 3, 4, 5, 6});
    ByteReader whole(data, "maps/x.bsp", 0);
    ByteReader lump = whole.sub(4, 2, "lump");
    lump.u8();
    try {
        lump.u32();
        FAIL() << "read past end accepted";
    } catch (const FormatError& e) {
        EXPECT_EQ(e.error().file, "maps/x.bsp");
        EXPECT_EQ(e.error().offset, 5u);  // 4 (lump start) + 1 byte already read
        EXPECT_EQ(e.error().to_string().rfind("maps/x.bsp: offset 5: ", 0), 0u);
    }
}

TEST(ByteReader, RestartReadsNewDataFromItsStartUnderTheSameName) {
    auto first = bytes({1, 2, 3});
    auto second = bytes({0x34, 0x12});
    ByteReader r(first, "demos/a_long_demo_name.dem", 100);
    r.u16();
    r.restart(second, 500);
    EXPECT_EQ(r.tell(), 0u);
    EXPECT_EQ(r.size(), 2u);
    EXPECT_EQ(r.u16(), 0x1234);
    try {
        r.u8();
        FAIL() << "read past the new data's end accepted";
    } catch (const FormatError& e) {
        EXPECT_EQ(e.error().file, "demos/a_long_demo_name.dem");
        EXPECT_EQ(e.error().offset, 502u);  // the new base + 2 bytes read
    }
}

TEST(ByteReader, SubRangeOutsideDataIsRefused) {
    auto data = bytes({1, 2, 3, 4});
    ByteReader r(data, "f");
    EXPECT_THROW(r.sub(2, 3, "lump"), FormatError);
    EXPECT_THROW(r.sub(5, 0, "lump"), FormatError);
    // A length that would overflow offset + length must not wrap around.
    EXPECT_THROW(r.sub(1, SIZE_MAX, "lump"), FormatError);
    EXPECT_NO_THROW(r.sub(4, 0, "empty lump"));
}

TEST(ByteReader, RecordCountsMustFitInRemainingBytes) {
    std::vector<uint8_t> data(40);
    ByteReader r(data, "f");
    EXPECT_NO_THROW(r.require_records(10, 4, "verts"));
    EXPECT_THROW(r.require_records(11, 4, "verts"), FormatError);
    EXPECT_THROW(r.require_records(-1, 4, "verts"), FormatError);
    EXPECT_THROW(r.require_records(INT64_MAX, 4, "verts"), FormatError);
}

TEST(ByteReader, StringsStopAtNulAndRequireTermination) {
    auto data = bytes({'a', 'b', 0, 'z', 'c', 'd', 'e'});
    ByteReader r(data, "f");
    EXPECT_EQ(r.fixed_string(4), "ab");
    EXPECT_THROW(r.c_string(), FormatError);  // "cde" has no terminator
}

TEST(CaptureErrors, TurnsThrowIntoReturnedError) {
    auto data = bytes({1});
    Result<int> r = capture_errors("f.mdl", [&] {
        ByteReader br(data, "f.mdl");
        return static_cast<int>(br.u32());
    });
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().file, "f.mdl");
    EXPECT_NE(r.error().message.find("unexpected end"), std::string::npos);
}

}  // namespace
}  // namespace nq

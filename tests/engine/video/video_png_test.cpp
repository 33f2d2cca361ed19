// PNG writing and reading, and Quake-style screenshot names. No GL needed.
#include <gtest/gtest.h>

#include <fstream>

#include "common/file_io.h"
#include "video/png_io.h"
#include "video/screenshot.h"
#include "support/engine_run.h"
#include "support/video_test_support.h"

namespace nq {
namespace {

using test::TempDir;

uint32_t big_endian_u32(const std::vector<uint8_t>& b, size_t at) {
    return uint32_t(b[at]) << 24 | uint32_t(b[at + 1]) << 16 | uint32_t(b[at + 2]) << 8 |
           uint32_t(b[at + 3]);
}

// A 5x3 image in which every byte differs, so swapped rows or channels show.
std::vector<uint8_t> gradient_5x3() {
    std::vector<uint8_t> rgb(5 * 3 * 3);
    for (size_t i = 0; i < rgb.size(); ++i) rgb[i] = static_cast<uint8_t>(i * 5 + 1);
    return rgb;
}

void touch(const std::string& path) {
    std::ofstream(path) << "x";
}

TEST(VideoPng, WritesAn8BitRgbPngWithTheRightHeader) {
    TempDir dir("nq_video");
    std::string path = dir.file("g.png");
    ASSERT_EQ(write_png(path, 5, 3, gradient_5x3()), "");
    auto bytes = read_file(path);
    ASSERT_TRUE(bytes);
    // PNG signature, then the IHDR chunk: length 13, "IHDR", width, height, depth, colour type.
    const uint8_t signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    ASSERT_GE(bytes->size(), 33u);
    EXPECT_TRUE(std::equal(signature, signature + 8, bytes->begin()));
    EXPECT_EQ(big_endian_u32(*bytes, 8), 13u);
    EXPECT_EQ(std::string(bytes->begin() + 12, bytes->begin() + 16), "IHDR");
    EXPECT_EQ(big_endian_u32(*bytes, 16), 5u);
    EXPECT_EQ(big_endian_u32(*bytes, 20), 3u);
    EXPECT_EQ((*bytes)[24], 8);  // bits per channel
    EXPECT_EQ((*bytes)[25], 2);  // colour type 2 = truecolour RGB, no alpha
}

TEST(VideoPng, ReadBackGivesTheSamePixels) {
    TempDir dir("nq_video");
    std::string path = dir.file("g.png");
    ASSERT_EQ(write_png(path, 5, 3, gradient_5x3()), "");
    auto image = read_png(path);
    ASSERT_TRUE(image) << image.error().message;
    EXPECT_EQ(image->width, 5);
    EXPECT_EQ(image->height, 3);
    EXPECT_EQ(image->rgb, gradient_5x3());
}

TEST(VideoPng, WrongBufferSizeIsRefused) {
    TempDir dir("nq_video");
    std::vector<uint8_t> short_buffer(5 * 3 * 3 - 1);
    std::string error = write_png(dir.file("s.png"), 5, 3, short_buffer);
    EXPECT_NE(error.find("44 bytes"), std::string::npos) << error;
    EXPECT_NE(error.find("needs 45"), std::string::npos) << error;
    EXPECT_NE(write_png(dir.file("z.png"), 0, 3, {}), "");
}

TEST(VideoPng, UnwritablePathNamesThePath) {
    std::string path = "/nonexistent_dir_for_nq_test/shot.png";
    std::string error = write_png(path, 5, 3, gradient_5x3());
    EXPECT_EQ(error.rfind(path, 0), 0u) << error;
}

TEST(VideoPng, NotAPngIsAnErrorNamingTheFile) {
    TempDir dir("nq_video");
    std::string path = dir.file("fake.png");
    std::ofstream(path) << "this is not a png file at all";
    auto image = read_png(path);
    ASSERT_FALSE(image);
    EXPECT_EQ(image.error().file, path);
    EXPECT_NE(image.error().message.find("cannot read PNG"), std::string::npos);
    EXPECT_FALSE(read_png(dir.file("missing.png")));
}

TEST(VideoScreenshotNames, FirstFreeNameInOrder) {
    TempDir dir("nq_video");
    auto first = next_screenshot_path(dir.path());
    ASSERT_TRUE(first) << first.error().message;
    EXPECT_EQ(*first, dir.file("nprq00.png"));

    touch(dir.file("nprq00.png"));
    touch(dir.file("nprq01.png"));
    touch(dir.file("nprq03.png"));
    auto next = next_screenshot_path(dir.path());
    ASSERT_TRUE(next);
    EXPECT_EQ(*next, dir.file("nprq02.png"));  // a gap is reused, as Quake does
}

TEST(VideoScreenshotNames, AllHundredTakenIsAnError) {
    TempDir dir("nq_video");
    for (int i = 0; i < 100; ++i) {
        char name[16];
        std::snprintf(name, sizeof name, "nprq%02d.png", i);
        touch(dir.file(name));
    }
    auto next = next_screenshot_path(dir.path());
    ASSERT_FALSE(next);
    EXPECT_NE(next.error().message.find("nprq99.png are taken"), std::string::npos);
}

TEST(VideoScreenshotNames, MissingDirectoryIsAnError) {
    auto next = next_screenshot_path("/nonexistent_dir_for_nq_test");
    ASSERT_FALSE(next);
    EXPECT_NE(next.error().message.find("does not exist"), std::string::npos);
}

}  // namespace
}  // namespace nq

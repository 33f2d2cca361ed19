// The line-quality measures (engine/quality/edge_quality.h) on synthetic frames whose outlines,
// lines and changes are counted here, and the edgequality tool on PNG files of them.
#include <gtest/gtest.h>

#include <fstream>

#include <string>
#include <vector>

#include "quality/edge_quality.h"
#include "support/engine_run.h"
#include "video/png_io.h"

namespace nq {
namespace {

using quality::PixelMask;

constexpr int kW = 40, kH = 30;
const uint8_t kGrey[3] = {90, 90, 90};

RgbImage filled(const uint8_t rgb[3]) {
    RgbImage image{kW, kH, std::vector<uint8_t>(size_t(kW) * kH * 3)};
    for (size_t i = 0; i < image.rgb.size(); ++i) image.rgb[i] = rgb[i % 3];
    return image;
}

void paint(RgbImage& image, int x0, int y0, int x1, int y1, quality::Rgb8 c) {
    for (int y = y0; y <= y1; ++y) {
        for (int x = x0; x <= x1; ++x) {
            uint8_t* p = &image.rgb[(size_t(y) * image.width + x) * 3];
            p[0] = c.r, p[1] = c.g, p[2] = c.b;
        }
    }
}

// The border of the rectangle [x0, x1] x [y0, y1], one pixel wide.
void frame(RgbImage& image, int x0, int y0, int x1, int y1, quality::Rgb8 c) {
    paint(image, x0, y0, x1, y0, c);
    paint(image, x0, y1, x1, y1, c);
    paint(image, x0, y0, x0, y1, c);
    paint(image, x1, y0, x1, y1, c);
}

const quality::Rgb8 kBlack{0, 0, 0};

TEST(EdgeQuality, IdColoursArePureAndWrapAfter24) {
    EXPECT_EQ(quality::id_colour(0), (quality::Rgb8{255, 0, 0}));
    EXPECT_EQ(quality::id_colour(5), (quality::Rgb8{0, 255, 255}));
    EXPECT_EQ(quality::id_colour(24), quality::id_colour(0));
    for (uint32_t i = 0; i < 24; ++i) {
        const quality::Rgb8 c = quality::id_colour(i);
        EXPECT_FALSE(c.r == c.g && c.g == c.b) << "colour " << i << " is a grey";
        for (uint32_t j = 0; j < i; ++j) EXPECT_FALSE(quality::id_colour(j) == c) << i << j;
    }
}

TEST(EdgeQuality, ARectanglesOutlineIsItsPerimeter) {
    RgbImage reference = filled(kGrey);
    paint(reference, 5, 4, 24, 19, quality::id_colour(3));  // 20 x 16
    const PixelMask outline = quality::id_outlines(reference);
    EXPECT_EQ(outline.count(), size_t(2 * 20 + 2 * 16 - 4));
    EXPECT_TRUE(outline.at(5, 4));
    EXPECT_TRUE(outline.at(24, 10));
    EXPECT_FALSE(outline.at(10, 10));
    EXPECT_EQ(quality::any_id_pixels(reference).count(), size_t(20 * 16));
}

TEST(EdgeQuality, TheImageBorderIsNoOutlineAndTouchingModelsBothKeepTheirs) {
    RgbImage reference = filled(kGrey);
    paint(reference, 0, 0, 9, 9, quality::id_colour(0));    // in the corner
    paint(reference, 10, 0, 19, 9, quality::id_colour(1));  // touching it
    const PixelMask outline = quality::id_outlines(reference);
    // Region 0: its right column (touching region 1) and bottom row; no top or left side.
    // Region 1: its left column, right column and bottom row.
    const size_t region0 = 10 + 10 - 1, region1 = 10 + 10 + 10 - 2;
    EXPECT_EQ(outline.count(), region0 + region1);
    EXPECT_FALSE(outline.at(0, 0));
    EXPECT_TRUE(outline.at(9, 0));
    EXPECT_TRUE(outline.at(10, 0));
}

TEST(EdgeQuality, LinesOnTheOutlineScoreFullAndStrayLinesLowerPrecision) {
    RgbImage reference = filled(kGrey);
    paint(reference, 5, 5, 24, 19, quality::id_colour(2));
    RgbImage drawn = reference;
    frame(drawn, 5, 5, 24, 19, kBlack);
    quality::SilhouetteScore s = quality::score_silhouettes(reference, drawn);
    EXPECT_DOUBLE_EQ(s.recall, 1.0);
    EXPECT_DOUBLE_EQ(s.precision, 1.0);
    EXPECT_EQ(s.line_pixels, s.outline_pixels);

    // A 10-pixel stray line far from the model: precision = outline / (outline + 10).
    paint(drawn, 28, 25, 37, 25, kBlack);
    s = quality::score_silhouettes(reference, drawn);
    EXPECT_DOUBLE_EQ(s.recall, 1.0);
    EXPECT_NEAR(s.precision, double(s.outline_pixels) / double(s.outline_pixels + 10), 1e-12);
    EXPECT_NEAR(s.on_models, s.precision, 1e-12);
}

TEST(EdgeQuality, RecallCountsTheOutlineCoveredWithinOnePixel) {
    RgbImage reference = filled(kGrey);
    paint(reference, 5, 5, 24, 19, quality::id_colour(2));  // 20 x 15
    RgbImage drawn = reference;
    // A line one pixel above the top side only: within 1 px of the top row's 20 outline
    // pixels, 2 px from the side columns' next pixels.
    paint(drawn, 5, 4, 24, 4, kBlack);
    const quality::SilhouetteScore s = quality::score_silhouettes(reference, drawn);
    const double outline = 2 * 20 + 2 * 15 - 4;
    EXPECT_NEAR(s.recall, 20 / outline, 1e-12);
    EXPECT_DOUBLE_EQ(s.precision, 1.0);
    // Black already in the reference is not a line.
    RgbImage dark = reference;
    paint(dark, 0, 0, 3, 3, kBlack);
    EXPECT_EQ(quality::line_pixels(dark, dark).count(), 0u);
}

TEST(EdgeQuality, ChangeRateCountsPixelsWithNoMatchWithinTheRadius) {
    PixelMask a{8, 1, {1, 1, 0, 0, 0, 0, 0, 0}}, b{8, 1, {0, 1, 1, 0, 0, 0, 0, 0}},
        c{8, 1, {0, 0, 0, 0, 0, 0, 1, 1}};
    std::vector<PixelMask> frames{a, b, c};
    // Radius 0, a -> b: pixel 0 vanished, pixel 2 appeared, of 4 present; b -> c: all 4 changed.
    EXPECT_NEAR(quality::change_rate(frames, 0), (2.0 / 4.0 + 4.0 / 4.0) / 2.0, 1e-12);
    // Radius 1: a one-pixel move is no change; c is 4 pixels away from b.
    EXPECT_NEAR(quality::change_rate(frames, 1), (0.0 + 4.0 / 4.0) / 2.0, 1e-12);
    EXPECT_EQ(quality::change_rate(std::span<const PixelMask>(frames.data(), 1)), 0.0);
}

TEST(EdgeQuality, FlickerIsWhatTheLinesChangeBeyondTheOutlines) {
    RgbImage reference = filled(kGrey);
    paint(reference, 5, 5, 24, 19, quality::id_colour(4));
    RgbImage steady = reference, blinking = reference;
    frame(steady, 5, 5, 24, 19, kBlack);
    frame(blinking, 5, 5, 24, 19, kBlack);
    paint(blinking, 30, 25, 39, 25, kBlack);  // 10 extra line pixels every other frame
    const std::vector<RgbImage> references{reference, reference, reference};
    const std::vector<RgbImage> drawn{steady, blinking, steady};
    const quality::FlickerScore f = quality::score_flicker(references, drawn);
    const double outline = 2 * 20 + 2 * 15 - 4;
    EXPECT_EQ(f.frames, 3u);
    EXPECT_EQ(f.outlines, 0.0);
    // Each pair: 10 pixels appear or vanish, of outline + (outline + 10) present.
    EXPECT_NEAR(f.lines, 10.0 / (2 * outline + 10.0), 1e-12);
    EXPECT_NEAR(f.excess, f.lines, 1e-12);
}

// The tool: options before or after the files give the same output; bad input says why.
TEST(EdgeQualityTool, ScoresPngFilesWithOptionsAnywhere) {
    test::TempDir dir("nq_edgequality");
    RgbImage reference = filled(kGrey);
    paint(reference, 5, 5, 24, 19, quality::id_colour(2));
    RgbImage drawn = reference;
    frame(drawn, 5, 5, 24, 19, kBlack);
    ASSERT_EQ(write_png(dir.file("ref.png"), kW, kH, reference.rgb), "");
    ASSERT_EQ(write_png(dir.file("drawn.png"), kW, kH, drawn.rgb), "");
    const test::ProcessResult after = test::run_tool(
        "edgequality", {"silhouettes", dir.file("ref.png"), dir.file("drawn.png"), "--json"});
    const test::ProcessResult before = test::run_tool(
        "edgequality", {"--json", "silhouettes", dir.file("ref.png"), dir.file("drawn.png")});
    ASSERT_EQ(after.exit_code, 0) << after.describe();
    EXPECT_EQ(after.out, before.out);
    EXPECT_NE(after.out.find("\"recall\": 1"), std::string::npos) << after.out;
    EXPECT_NE(after.out.find("\"line_pixels\": 66"), std::string::npos) << after.out;

    const test::ProcessResult flicker =
        test::run_tool("edgequality", {"flicker", dir.file("ref.png"), dir.file("drawn.png"),
                                       dir.file("ref.png"), dir.file("drawn.png")});
    ASSERT_EQ(flicker.exit_code, 0) << flicker.describe();
    EXPECT_NE(flicker.out.find("lines change 0.0000"), std::string::npos) << flicker.out;
}

TEST(EdgeQualityTool, BadInputAndBadCommandLines) {
    test::TempDir dir("nq_edgequality");
    RgbImage small{4, 4, std::vector<uint8_t>(4 * 4 * 3, 0)};
    ASSERT_EQ(write_png(dir.file("small.png"), 4, 4, small.rgb), "");
    RgbImage big = filled(kGrey);
    ASSERT_EQ(write_png(dir.file("big.png"), kW, kH, big.rgb), "");
    std::ofstream(dir.file("junk.png")) << "not a png";

    test::ProcessResult r =
        test::run_tool("edgequality", {"silhouettes", dir.file("junk.png"), dir.file("big.png")});
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("junk.png"), std::string::npos) << r.err;
    r = test::run_tool("edgequality", {"silhouettes", dir.file("big.png"), dir.file("small.png")});
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("small.png: 4x4"), std::string::npos) << r.err;
    for (const std::vector<std::string>& args :
         std::vector<std::vector<std::string>>{{},
                                               {"silhouettes", "a.png"},
                                               {"flicker", "a", "b"},
                                               {"frob", "a", "b"},
                                               {"--bogus"}}) {
        r = test::run_tool("edgequality", args);
        EXPECT_EQ(r.exit_code, 2);
        EXPECT_NE(r.err.find("usage: edgequality"), std::string::npos);
    }
    r = test::run_tool("edgequality", {"--help"});
    EXPECT_EQ(r.exit_code, 0);
    EXPECT_NE(r.out.find("usage: edgequality"), std::string::npos);
}

}  // namespace
}  // namespace nq

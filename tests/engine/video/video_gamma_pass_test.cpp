// The `gamma` pass: the finished frame's channels become channel^gamma (QuakeSpasm's rule),
// checked on a cleared offscreen window against values worked out by hand; gamma 1 leaves
// every pixel as it was, and the pass puts back the GL state it touched.
#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <cmath>

#include "video/gamma_pass.h"
#include "video/screenshot.h"
#include "support/video_test_support.h"

namespace nq {
namespace {

std::array<int, 3> centre_after(GammaPass& pass, float gamma, float grey) {
    glClearColor(grey, grey / 2, 1.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    pass.apply({gamma, 1.0f}, 64, 48);
    auto image = read_framebuffer_rgb(0, 64, 48);
    EXPECT_TRUE(image) << image.error().message;
    if (!image) return {};
    size_t at = (24 * 64 + 32) * 3;
    return {image->rgb[at], image->rgb[at + 1], image->rgb[at + 2]};
}

TEST(GammaPass, RaisesEachChannelToTheGammaPower) {
    auto window = test::make_offscreen_window(64, 48);
    ASSERT_TRUE(window) << window.error().message;
    auto pass = GammaPass::create();
    ASSERT_TRUE(pass) << pass.error().message;

    // 128 / 255 = 0.502: ^0.5 = 0.7085 (181), ^2 = 0.252 (64); 64 / 255 -> ^0.5 = 0.501 (128).
    std::array<int, 3> bright = centre_after(*pass, 0.5f, 128 / 255.0f);
    EXPECT_NEAR(bright[0], 181, 1);
    EXPECT_NEAR(bright[1], 128, 1);
    EXPECT_EQ(bright[2], 255);
    std::array<int, 3> dark = centre_after(*pass, 2.0f, 128 / 255.0f);
    EXPECT_NEAR(dark[0], 64, 1);
    EXPECT_NEAR(dark[1], 16, 1);
    EXPECT_EQ(dark[2], 255);
    std::array<int, 3> same = centre_after(*pass, 1.0f, 128 / 255.0f);
    EXPECT_NEAR(same[0], 128, 1);
    EXPECT_NEAR(same[1], 64, 1);
}

TEST(GammaPass, PutsBackTheStateItChanges) {
    auto window = test::make_offscreen_window(64, 48);
    ASSERT_TRUE(window) << window.error().message;
    auto pass = GammaPass::create();
    ASSERT_TRUE(pass) << pass.error().message;
    glEnable(GL_BLEND);
    glEnable(GL_DEPTH_TEST);
    glViewport(3, 4, 20, 10);
    pass->apply({0.7f, 1.0f}, 64, 48);
    EXPECT_TRUE(glIsEnabled(GL_BLEND));
    EXPECT_TRUE(glIsEnabled(GL_DEPTH_TEST));
    GLint viewport[4] = {};
    glGetIntegerv(GL_VIEWPORT, viewport);
    EXPECT_EQ(viewport[0], 3);
    EXPECT_EQ(viewport[2], 20);
    GLint program = -1;
    glGetIntegerv(GL_CURRENT_PROGRAM, &program);
    EXPECT_EQ(program, 0);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

}  // namespace
}  // namespace nq

// The post-process path: a plugin that sets NQR_WANTS_GBUFFER gets the scene as colour, normal
// and depth textures. The test plugin (tests/plugins/test_plugin.c, kind "post") draws nothing
// itself — the engine's default drawers render the showroom into the G-buffer — and its
// post_process copies the *normal* buffer to the screen. The screenshot must therefore show
// encoded view-space normals: the clear value where there is no geometry, and for the floor
// (facing up, seen from above at a downward pitch) a normal with no sideways part that leans
// toward the viewer and up the screen.
#include <gtest/gtest.h>

#include "support/build_paths.h"
#include "support/engine_run.h"
#include "video/png_io.h"

namespace nq {
namespace {

struct Pixel {
    int r, g, b;
};

Pixel at(const RgbImage& img, int x, int y) {
    const uint8_t* p = &img.rgb[(static_cast<size_t>(y) * img.width + x) * 3];
    return {p[0], p[1], p[2]};
}

// With obscurance on as well, the plugin's post-process still draws the window (obscurance
// darkens the G-buffer's colour in place and writes nothing there itself).
class EnginePostProcess : public ::testing::TestWithParam<const char*> {};

TEST_P(EnginePostProcess, PluginSeesTheSceneNormalsBuffer) {
    test::TempDir tmp("nq_post");
    std::string shot = tmp.file("normals.png");
    std::string empty_base = tmp.subdir("nodata");  // no game data: the showroom
    auto run = test::run_nprquake(
        {"-userdir", tmp.path(), "-basedir", empty_base, "-width", "160", "-height", "120",
         "-plugindir", test::test_plugin_dir(), "+vo_enable", GetParam(), "+r_plugin", "test_post",
         "+wait", "+wait", "+screenshot", shot, "+quit"},
        tmp.path());
    ASSERT_EQ(run.exit_code, 0) << run.describe();
    ASSERT_NE(run.out.find("renderer: probe"), std::string::npos) << run.out;
    auto img = read_png(shot);
    ASSERT_TRUE(img.ok()) << img.error().to_string();

    // Top left: sky, nothing drawn: the clear value (0, 0, 1) encoded.
    Pixel sky = at(*img, 2, 2);
    EXPECT_NEAR(sky.r, 128, 3);
    EXPECT_NEAR(sky.g, 128, 3);
    EXPECT_NEAR(sky.b, 255, 3);

    // Bottom centre: the floor. Up in the world is up the screen (+y) and toward the camera
    // (+z) in view space; the camera has no roll, so x stays 0.
    Pixel floor = at(*img, img->width / 2, img->height - 3);
    EXPECT_NEAR(floor.r, 128, 12);
    EXPECT_GT(floor.g, 180);  // y = cos(pitch) > 0.4
    EXPECT_GT(floor.b, 150);  // z = sin(pitch) > 0.2
    EXPECT_LT(floor.b, 250);
}

INSTANTIATE_TEST_SUITE_P(ObscuranceOffAndOn, EnginePostProcess, ::testing::Values("0", "1"));

}  // namespace
}  // namespace nq

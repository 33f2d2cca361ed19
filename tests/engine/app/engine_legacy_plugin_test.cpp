// A plugin built for ABI 1.5 (tests/plugins/legacy_1_5_plugin.c, compiled from the 1.5 header)
// loads and draws under the 2.0 engine. In the showroom it clears the world to one colour and
// marks each alias entity with a square where its 1.x camera's view_projection puts the
// entity's origin, green from the entity's ambient light; its console command logs the camera
// and the entities it was handed. The test projects those origins itself with Quake's
// conventions (engine_projection.h, none of the engine's matrix code) from the logged eye,
// angles and fov, and finds each square there: the converted camera and entities agree with
// each other, and the plugin's context-free services (GL, cvar, command, log) all work.
#include <gtest/gtest.h>

#include <cstdio>

#include "engine_projection.h"
#include "support/build_paths.h"
#include "support/engine_output_checks.h"
#include "support/engine_run.h"
#include "video/png_io.h"

namespace nq {
namespace {

struct Seen {
    test::V3 origin{};
    float ambient = 0;
};

TEST(EngineLegacyPlugin, APluginBuiltForAbi15DrawsUnderTheEngine) {
    constexpr int kW = 320, kH = 240;
    test::TempDir tmp("nq_legacy15");
    const std::string shot = tmp.file("legacy.png");
    auto run = test::run_nprquake(
        {"-userdir", tmp.path(), "-basedir", tmp.subdir("nodata"), "-width", std::to_string(kW),
         "-height", std::to_string(kH), "-plugindir", test::test_plugin_dir(), "+r_plugin",
         "legacy15", "+wait", "+wait", "+screenshot", shot, "+legacy15_report", "+quit"},
        tmp.path());
    ASSERT_EQ(run.exit_code, 0) << run.describe();
    ASSERT_NE(run.out.find("legacy15: a 1.5 plugin is running"), std::string::npos) << run.out;
    ASSERT_NE(run.out.find("renderer: legacy15"), std::string::npos) << run.out;

    test::V3 eye{}, angles{};
    float fov_x = 0;
    int width = 0, height = 0;
    const auto cameras = test::lines_containing(run.out, "legacy15 camera");
    ASSERT_EQ(cameras.size(), 1u) << run.out;
    ASSERT_EQ(std::sscanf(cameras[0].c_str(),
                          "legacy15 camera %f %f %f angles %f %f %f fov %f %d %d", &eye[0], &eye[1],
                          &eye[2], &angles[0], &angles[1], &angles[2], &fov_x, &width, &height),
              9)
        << cameras[0];
    EXPECT_EQ(width, kW);
    EXPECT_EQ(height, kH);
    std::vector<Seen> seen;
    for (const std::string& line : test::lines_containing(run.out, "legacy15 entity")) {
        Seen s;
        unsigned lights = 0;
        ASSERT_EQ(std::sscanf(line.c_str(), "legacy15 entity %f %f %f ambient %f lights %u",
                              &s.origin[0], &s.origin[1], &s.origin[2], &s.ambient, &lights),
                  5)
            << line;
        EXPECT_GE(lights, 1u) << "the showroom's lamp reaches every model: " << line;
        seen.push_back(s);
    }
    ASSERT_GE(seen.size(), 2u) << "the showroom's models" << run.out;

    auto img = read_png(shot);
    ASSERT_TRUE(img.ok()) << img.error().to_string();
    ASSERT_EQ(img->width, kW);
    auto pixel = [&](int x, int y) { return &img->rgb[(size_t(y) * kW + x) * 3]; };
    // The world: the plugin's flat clear (0, 0.25, 0.75), in every corner.
    for (auto [x, y] : {std::pair{1, 1}, {kW - 2, 1}, {1, kH - 2}, {kW - 2, kH - 2}}) {
        const uint8_t* p = pixel(x, y);
        EXPECT_NEAR(p[0], 0, 1);
        EXPECT_NEAR(p[1], 64, 1);
        EXPECT_NEAR(p[2], 191, 1);
    }
    const test::QuakeProjector projector(eye, angles, fov_x, kW, kH);
    for (const Seen& s : seen) {
        const auto at = projector.project(s.origin);
        ASSERT_TRUE(at) << "an entity behind the eye was marked";
        const int x = int(at->x), y = int(at->y);
        SCOPED_TRACE("marker expected at " + std::to_string(x) + ", " + std::to_string(y));
        ASSERT_TRUE(x >= 2 && y >= 2 && x < kW - 2 && y < kH - 2);
        const uint8_t* p = pixel(x, y);
        EXPECT_EQ(p[0], 255);
        EXPECT_NEAR(p[1], std::min(255.0f, s.ambient * 100.0f), 2.0f);
        EXPECT_EQ(p[2], 0);
    }
}

}  // namespace
}  // namespace nq

// The ray-traced obscurance reference (nprlib/obscurance/reference_tool, Embree) against
// volumes computed here: a floor meeting a wall, seen through a 90-degree camera; on the floor
// at distance h from the wall the wall cuts a cap of height R - h off the ball, half of it above
// the floor, so the open fraction of the half-ball is 1 - (R - h)^2 (2R + h) / (4 R^3); far from
// the wall it is 1. What the camera sees through nothing is open, and so is a surface that is
// not solid (sky, liquid), which also blocks nothing.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "raytraced_obscurance.h"

namespace nq::npr::obscurance {
namespace {

constexpr uint32_t kSide = 64;
constexpr float kRadius = 24.0f;

// A quad as two triangles.
void add_quad(ObscuranceScene& scene, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d,
              bool solid) {
    scene.triangles.push_back({a, b, c, solid});
    scene.triangles.push_back({a, c, d, solid});
}

ObscuranceScene floor_and_wall() {
    ObscuranceScene scene;
    scene.width = scene.height = kSide;
    const glm::mat4 projection = glm::perspective(glm::radians(90.0f), 1.0f, 4.0f, 4096.0f);
    std::copy_n(glm::value_ptr(projection), 16, scene.projection);
    // Floor y = -40 from the camera to the wall z = -160; the wall from the floor up.
    add_quad(scene, {-500, -40, 0}, {500, -40, 0}, {500, -40, -160}, {-500, -40, -160}, true);
    add_quad(scene, {-500, -40, -160}, {500, -40, -160}, {500, 500, -160}, {-500, 500, -160}, true);
    return scene;
}

float open_near_wall(float h) {
    if (h >= kRadius) return 1.0f;
    return 1.0f - (kRadius - h) * (kRadius - h) * (2.0f * kRadius + h) /
                      (4.0f * kRadius * kRadius * kRadius);
}

// Where pixel (x, y)'s ray meets the floor (y = -40), or nothing when it looks above it or
// reaches the wall first.
bool floor_point(uint32_t x, uint32_t y, glm::vec3& point) {
    const glm::vec3 ray((float(x) + 0.5f) / (kSide / 2.0f) - 1.0f,
                        (float(y) + 0.5f) / (kSide / 2.0f) - 1.0f, -1.0f);
    if (ray.y >= -1e-4f) return false;
    point = ray * (-40.0f / ray.y);
    return point.z > -160.0f;
}

TEST(ObscuranceRaytrace, AFloorMeetingAWallIsOpenByTheVolumeTheWallLeaves) {
    RaytraceOptions options;
    options.radius = kRadius;
    options.directions_per_side = 16;
    const RaytraceResult result = raytrace_obscurance(floor_and_wall(), options);
    ASSERT_TRUE(result.error.empty()) << result.error;
    ASSERT_EQ(result.open.size(), size_t(kSide) * kSide);
    double error = 0.0, near_wall = 0.0;
    int counted = 0, near = 0;
    for (uint32_t y = 0; y < kSide; ++y) {
        for (uint32_t x = 0; x < kSide; ++x) {
            glm::vec3 p;
            if (!floor_point(x, y, p)) continue;
            const float h = p.z + 160.0f;
            const float drawn = result.open[size_t(y) * kSide + x];
            error += std::abs(drawn - open_near_wall(h));
            ++counted;
            if (h < 0.5f * kRadius) {
                near_wall += drawn;
                ++near;
            }
        }
    }
    ASSERT_GT(counted, 200);
    ASSERT_GT(near, 20);
    EXPECT_LT(error / counted, 0.01);
    EXPECT_LT(near_wall / near, 0.85);  // the truth there: 0.59 to 0.84
}

TEST(ObscuranceRaytrace, NothingAndSurfacesThatAreNotSolidStayOpen) {
    ObscuranceScene scene = floor_and_wall();
    // A liquid sheet just above the floor's near half: seen first by the rays below the horizon
    // on that side, so those pixels are open; it blocks none of the floor's rays either.
    add_quad(scene, {-500, -39, 0}, {0, -39, 0}, {0, -39, -160}, {-500, -39, -160}, false);
    RaytraceOptions options;
    options.radius = kRadius;
    options.directions_per_side = 8;
    const RaytraceResult with_sheet = raytrace_obscurance(scene, options);
    const RaytraceResult without = raytrace_obscurance(floor_and_wall(), options);
    ASSERT_TRUE(with_sheet.error.empty() && without.error.empty());
    ASSERT_EQ(with_sheet.open.size(), without.open.size());
    int sheet = 0, floor_kept = 0;
    for (uint32_t y = 0; y < kSide; ++y) {
        for (uint32_t x = 0; x < kSide; ++x) {
            const size_t i = size_t(y) * kSide + x;
            glm::vec3 p;
            if (!floor_point(x, y, p)) continue;
            if (p.x < -1.0f) {  // under the sheet: the camera sees the sheet
                EXPECT_EQ(with_sheet.open[i], 1.0f);
                ++sheet;
            } else if (p.x > 30.0f) {  // beside it, beyond the radius: as without it
                EXPECT_EQ(with_sheet.open[i], without.open[i]);
                ++floor_kept;
            }
        }
    }
    EXPECT_GT(sheet, 100);
    EXPECT_GT(floor_kept, 50);
}

}  // namespace
}  // namespace nq::npr::obscurance

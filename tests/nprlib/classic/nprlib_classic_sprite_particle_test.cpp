// Sprites (orientation types, index-255 transparency) and particles (palette colour, GLQuake's
// distance scaling, blending, streaming through both ring-buffer strategies).
#include <gtest/gtest.h>

#include <cmath>

#include "classic/classic_renderer.h"
#include "classic/particle_drawer.h"
#include "classic/sprite_orientation.h"
#include "classic_renderer_suite.h"
#include "support/nprlib_test_support.h"

namespace nq::npr::test {
namespace {

using classic::ClassicRenderer;

void expect_vec_near(glm::vec3 actual, glm::vec3 expected) {
    EXPECT_NEAR(actual.x, expected.x, 1e-5f) << "x";
    EXPECT_NEAR(actual.y, expected.y, 1e-5f) << "y";
    EXPECT_NEAR(actual.z, expected.z, 1e-5f) << "z";
}

// ------------------------------------------------------------------ CPU: sprite axes

classic::SpriteView pitched_view() {
    // Looking along +X, pitched 30 degrees down: right = -Y, up tilted forward.
    const float s = std::sin(glm::radians(30.0f)), c = std::cos(glm::radians(30.0f));
    return {{0, 0, 0}, {0, -1, 0}, {s, 0, c}};
}

TEST(SpriteAxes, ParallelUprightKeepsWorldUp) {
    const auto axes = classic::sprite_axes(0, pitched_view(), {100, 0, 0}, {0, 0, 0});
    expect_vec_near(axes.right, {0, -1, 0});
    expect_vec_near(axes.up, {0, 0, 1});
}

TEST(SpriteAxes, FacingUprightTurnsTowardTheEyeAboutZ) {
    classic::SpriteView view = pitched_view();
    view.eye = {0, 0, 50};
    // Sprite due +Y of the eye: its right is perpendicular to that, i.e. +X.
    const auto axes = classic::sprite_axes(1, view, {0, 100, 0}, {0, 0, 0});
    expect_vec_near(axes.right, {1, 0, 0});
    expect_vec_near(axes.up, {0, 0, 1});
}

TEST(SpriteAxes, ParallelUsesTheViewAxes) {
    const auto view = pitched_view();
    const auto axes = classic::sprite_axes(2, view, {100, 0, 0}, {0, 0, 0});
    expect_vec_near(axes.right, view.right);
    expect_vec_near(axes.up, view.up);
}

TEST(SpriteAxes, OrientedUsesTheEntityAngles) {
    // Yaw 90: the entity faces +Y, so its right is +X; up stays +Z.
    const auto axes = classic::sprite_axes(3, pitched_view(), {0, 0, 0}, {0, 90, 0});
    expect_vec_near(axes.right, {1, 0, 0});
    expect_vec_near(axes.up, {0, 0, 1});
}

TEST(SpriteAxes, ParallelOrientedRollsTheViewAxes) {
    const auto view = pitched_view();
    const auto axes = classic::sprite_axes(4, view, {0, 0, 0}, {0, 0, 90});
    expect_vec_near(axes.right, view.up);
    expect_vec_near(axes.up, -view.right);
}

TEST(SpriteAxes, QuakeAngleVectorsAtZeroAreForwardXRightMinusYUpZ) {
    glm::vec3 f, r, u;
    classic::quake_angle_vectors({0, 0, 0}, &f, &r, &u);
    expect_vec_near(f, {1, 0, 0});
    expect_vec_near(r, {0, -1, 0});
    expect_vec_near(u, {0, 0, 1});
    classic::quake_angle_vectors({90, 0, 0}, &f, nullptr, nullptr);  // pitch down
    expect_vec_near(f, {0, 0, -1});
}

// ------------------------------------------------------------------ GPU

class ClassicSpriteParticleTest : public ClassicRendererSuite<ClassicSpriteParticleTest> {
  protected:
    std::vector<Rgb> draw(TestFrame& frame, const nqr_camera& camera, Rgb clear = {}) {
        gl_->clear(clear);
        const nqr_frame* f = frame.build(camera, 0);
        renderer_.draw_sprite_entities(f);
        renderer_.draw_particles(f);
        EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
        return gl_->pixels();
    }

    Rgb at(const nqr_camera& camera, glm::vec3 world) const {
        const glm::vec2 p = project(camera, world);
        return gl_->pixel(static_cast<int>(p.x), static_cast<int>(p.y));
    }
};

nqr_camera front_camera(float distance = 64.0f, float fov = 90.0f) {
    return make_camera({-distance, 0.0f, 0.0f}, {0.0f, 0.0f, 0.0f}, fov);
}

TEST_F(ClassicSpriteParticleTest, SpriteShowsItsImageAndIndex255ShowsTheBackground) {
    SpriteBuilder sprite;
    // 16 x 16, top-left 8 left of and 8 above the origin; left half red, right half clear.
    sprite.images.push_back({16, 16, -8, 8, make_image(16, 16, [](int x, int) {
                                 return x < 8 ? colour::kRed : colour::kTransparent;
                             })});
    nqr_model model = sprite.model(1);
    renderer_.register_model(&model);
    nqr_entity entity = make_entity(1);
    TestFrame frame;
    frame.sprite.push_back(&entity);
    const nqr_camera camera = front_camera();
    const Rgb background{0, 60, 0};
    draw(frame, camera, background);
    // Screen left is world +Y: the image's left half covers y in (0, 8).
    EXPECT_TRUE(near(at(camera, {0, 4, 4}), colour(colour::kRed), 2)) << at(camera, {0, 4, 4});
    EXPECT_TRUE(near(at(camera, {0, 4, -4}), colour(colour::kRed), 2));
    EXPECT_EQ(at(camera, {0, -4, 4}), background);
    EXPECT_EQ(at(camera, {0, -4, -4}), background);
    EXPECT_EQ(at(camera, {0, 12, 0}), background);  // outside the quad
}

TEST_F(ClassicSpriteParticleTest, SpriteDrawsTheImageOfPose0) {
    SpriteBuilder sprite;
    sprite.images.push_back({8, 8, -4, 4, make_image(8, 8, [](int, int) { return colour::kRed; })});
    sprite.images.push_back(
        {8, 8, -4, 4, make_image(8, 8, [](int, int) { return colour::kBlue; })});
    nqr_model model = sprite.model(1);
    renderer_.register_model(&model);
    nqr_entity entity = make_entity(1);
    entity.pose0 = 1;
    TestFrame frame;
    frame.sprite.push_back(&entity);
    const nqr_camera camera = front_camera();
    draw(frame, camera);
    EXPECT_TRUE(near(at(camera, {0, 0, 0}), colour(colour::kBlue), 2));
}

TEST_F(ClassicSpriteParticleTest, OrientedSpriteSeenEdgeOnDisappears) {
    SpriteBuilder sprite;
    sprite.type = 3;  // oriented
    sprite.images.push_back(
        {16, 16, -8, 8, make_image(16, 16, [](int, int) { return colour::kRed; })});
    nqr_model model = sprite.model(1);
    renderer_.register_model(&model);
    nqr_entity entity = make_entity(1);
    TestFrame frame;
    frame.sprite.push_back(&entity);
    const nqr_camera camera = front_camera();
    // Yaw 0: the sprite plane holds the entity's right (-Y) and up: it faces the camera.
    draw(frame, camera);
    EXPECT_GT(coverage(gl_->pixels(), {}).count, 100);
    // Yaw 90: its plane is X-Z, seen exactly edge-on from -X.
    entity.angles[1] = 90.0f;
    draw(frame, camera);
    EXPECT_LT(coverage(gl_->pixels(), {}).count, 40);
}

TEST_F(ClassicSpriteParticleTest, ParticleShowsItsPaletteColourWhereProjected) {
    TestFrame frame;
    frame.particles.push_back(make_particle({0, 0, 0}, colour::kOrange));
    const nqr_camera camera = front_camera(10.0f);
    const std::vector<Rgb> pixels = draw(frame, camera);
    EXPECT_TRUE(near(at(camera, {0, 0, 0}), colour(colour::kOrange), 2));
    const Coverage c = coverage(pixels, {}, 4);
    // Closer than 20 units: scale 1, one unit across = 6.4 pixels at distance 10.
    EXPECT_NEAR(c.max_x - c.min_x + 1, 6.4, 1.5);
    EXPECT_NEAR(c.centroid.x, 64.0f, 0.6f);
    EXPECT_NEAR(c.centroid.y, 64.0f, 0.6f);
}

TEST_F(ClassicSpriteParticleTest, ParticlesGrowWithDistanceLikeGLQuake) {
    // A 10 degree field of view: 64 / tan(5 deg) = 731.5 pixels per unit at distance 1.
    const double focal = 64.0 / std::tan(glm::radians(5.0));
    auto width_at = [&](float distance) {
        TestFrame frame;
        frame.particles.push_back(make_particle({0, 0, 0}, colour::kOrange));
        const Coverage c = coverage(draw(frame, front_camera(distance, 10.0f)), {}, 4);
        return c.max_x - c.min_x + 1;
    };
    const int near_width = width_at(100.0f);  // scale 1 + 100 x 0.004 = 1.4
    const int far_width = width_at(300.0f);   // scale 2.2
    EXPECT_NEAR(near_width, focal * 1.4 / 100.0, 2.0);
    EXPECT_NEAR(far_width, focal * 2.2 / 300.0, 2.0);
    EXPECT_GT(far_width, focal * 1.0 / 300.0 + 1.0);  // larger than an unscaled dot
}

TEST_F(ClassicSpriteParticleTest, ParticleAlphaBlends) {
    TestFrame frame;
    frame.particles.push_back(make_particle({0, 0, 0}, colour::kRed, 0.5f));
    const nqr_camera camera = front_camera(10.0f);
    const Rgb background{0, 100, 0};
    draw(frame, camera, background);
    const Rgb red = colour(colour::kRed);
    EXPECT_TRUE(near(at(camera, {0, 0, 0}), (Rgb{red.r / 2, (red.g + 100) / 2, red.b / 2}), 3))
        << at(camera, {0, 0, 0});
}

TEST_F(ClassicSpriteParticleTest, ManyParticlesAreDrawnInChunks) {
    TestFrame frame;
    // 20000 particles behind the camera, then one in view: drawn in the third chunk.
    for (int i = 0; i < 20000; ++i) frame.particles.push_back(make_particle({-100, 0, 0}, 1));
    frame.particles.push_back(make_particle({0, 0, 0}, colour::kBlue));
    const nqr_camera camera = front_camera(10.0f);
    draw(frame, camera);
    EXPECT_TRUE(near(at(camera, {0, 0, 0}), colour(colour::kBlue), 2));
}

TEST_F(ClassicSpriteParticleTest, OrphaningStreamDrawsTheSameAsPersistent) {
    if (!gl::context_supports_buffer_storage()) GTEST_SKIP() << "no GL 4.4 buffer storage";
    gl::ObjectTracker tracker;
    std::vector<Rgb> images[2];
    const gl::StreamBuffer::Mode modes[2] = {gl::StreamBuffer::Mode::persistent,
                                             gl::StreamBuffer::Mode::orphaning};
    TestFrame frame;
    for (int i = 0; i < 50; ++i) {
        frame.particles.push_back(
            make_particle({0, (i % 10) - 5.0f, (i / 10) - 2.5f}, colour::kRed + i % 4));
    }
    const nqr_camera camera = front_camera(20.0f);
    for (int m = 0; m < 2; ++m) {
        classic::ParticleDrawer drawer;
        std::string error;
        ASSERT_TRUE(drawer.init(&tracker, engine_.palette.data(), error, modes[m])) << error;
        EXPECT_EQ(drawer.stream().mode(), modes[m]);
        gl_->clear();
        for (int repeat = 0; repeat < 3; ++repeat) drawer.draw_particles(*frame.build(camera, 0));
        images[m] = gl_->pixels();
        drawer.reset();
    }
    EXPECT_EQ(tracker.total_live(), 0);
    EXPECT_GT(coverage(images[0], {}).count, 200);
    EXPECT_EQ(images[0], images[1]);
}

}  // namespace
}  // namespace nq::npr::test

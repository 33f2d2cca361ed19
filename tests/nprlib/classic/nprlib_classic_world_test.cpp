// ClassicRenderer's brush drawing, rendered offscreen and checked pixel by pixel: lightmap
// scaling (QuakeSpasm overbright), light styles, fullbrights, dynamic lights, texture animation,
// sky layers, warped liquids, brush entities and the visible-surface list.
#include <gtest/gtest.h>

#include <cmath>

#include "classic/classic_renderer.h"
#include "classic/lightmap_atlas.h"
#include "classic/surface_batches.h"
#include "classic_renderer_suite.h"
#include "support/nprlib_test_support.h"

namespace nq::npr::test {
namespace {

using classic::ClassicRenderer;

// Looking straight down from height 64 with a 90 degree field of view: the 128 x 128 units
// below map one unit to one pixel (world +X up the screen, +Y to the left).
nqr_camera floor_camera() {
    return make_camera({64.0f, 64.0f, 64.0f}, {90.0f, 0.0f, 0.0f});
}

Rgb floor_pixel(const GlTestContext& gl, const nqr_camera& camera, float x, float y) {
    const glm::vec2 p = project(camera, {x, y, 0.0f});
    return gl.pixel(static_cast<int>(p.x), static_cast<int>(p.y));
}

// QuakeSpasm: stored = min(255, sample x 264/256 per unit of style), drawn x 2 / 255.
double lit_channel(int texture_channel, double sample, double style = 1.0) {
    const double stored = std::min(255.0, std::floor(sample * style * 264.0 / 256.0));
    return texture_channel * stored / 255.0 * 2.0;
}

Rgb lit(const Rgb& texture, double sample, double style = 1.0) {
    return {static_cast<int>(std::lround(std::min(255.0, lit_channel(texture.r, sample, style)))),
            static_cast<int>(std::lround(std::min(255.0, lit_channel(texture.g, sample, style)))),
            static_cast<int>(std::lround(std::min(255.0, lit_channel(texture.b, sample, style))))};
}

std::vector<uint8_t> uniform_image(int size, uint8_t index) {
    return make_image(size, size, [&](int, int) { return index; });
}

class ClassicWorldTest : public ClassicRendererSuite<ClassicWorldTest> {
  protected:
    // Registers the built brush model as the world (id 1) covering surfaces [0, count).
    void register_world(BrushBuilder& builder, uint32_t count, bool with_lighting = true) {
        builder.build(with_lighting);
        nqr_model model = builder.model(1, 0, count);
        renderer_.register_model(&model);
        ASSERT_NE(renderer_.models().find(1), nullptr);
    }

    void draw(TestFrame& frame, const nqr_camera& camera, double time = 0.0, Rgb clear = {}) {
        gl_->clear(clear);
        const nqr_frame* f = frame.build(camera, 1, time);
        renderer_.draw_world(f);
        renderer_.draw_brush_entities(f);
        ASSERT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    }
};

TEST_F(ClassicWorldTest, FloorIsTextureScaledByLightmapWithOverbright) {
    BrushBuilder builder;
    const int orange = builder.add_texture("floor", 16, 16, uniform_image(16, colour::kOrange));
    BrushBuilder::Quad dim{0, 0, 64, 128, 0, orange};
    dim.light = {128, 0, 0, 0};
    BrushBuilder::Quad bright{64, 0, 128, 128, 0, orange};
    bright.light = {255, 0, 0, 0};
    builder.add_floor(dim);
    builder.add_floor(bright);
    register_world(builder, 2);
    TestFrame frame;
    const nqr_camera camera = floor_camera();
    draw(frame, camera);

    const Rgb texture = colour(colour::kOrange);
    const Rgb at_128 = floor_pixel(*gl_, camera, 32, 64);
    const Rgb at_255 = floor_pixel(*gl_, camera, 96, 64);
    EXPECT_TRUE(near(at_128, lit(texture, 128), 2)) << at_128 << " vs " << lit(texture, 128);
    EXPECT_TRUE(near(at_255, lit(texture, 255), 2)) << at_255 << " vs " << lit(texture, 255);
    // Sample 255 is about twice sample 128 (QuakeSpasm's overbright: 255 -> x2, 128 -> x1.04).
    const double ratio = static_cast<double>(at_255.r) / at_128.r;
    EXPECT_NEAR(ratio, 255.0 / 132.0, 0.05);
}

TEST_F(ClassicWorldTest, TwoColourTextureAppearsWhereMapped) {
    BrushBuilder builder;
    // 16 x 16: columns 0..7 red, 8..15 blue; 1/8 texel per unit: red on x in [0, 64).
    const int two = builder.add_texture("two", 16, 16, make_image(16, 16, [](int x, int) {
                                            return x < 8 ? colour::kRed : colour::kBlue;
                                        }));
    BrushBuilder::Quad quad{0, 0, 128, 128, 0, two, 0.125f};
    builder.add_floor(quad);
    register_world(builder, 1);
    TestFrame frame;
    const nqr_camera camera = floor_camera();
    draw(frame, camera);
    EXPECT_TRUE(near(floor_pixel(*gl_, camera, 30, 64), lit(colour(colour::kRed), 128), 2));
    EXPECT_TRUE(near(floor_pixel(*gl_, camera, 98, 64), lit(colour(colour::kBlue), 128), 2));
}

TEST_F(ClassicWorldTest, LightStyleZeroIsBlackAndHalfIsHalf) {
    BrushBuilder builder;
    const int orange = builder.add_texture("floor", 16, 16, uniform_image(16, colour::kOrange));
    BrushBuilder::Quad quad{0, 0, 128, 128, 0, orange};
    quad.styles = {5, 255, 255, 255};
    quad.light = {200, 0, 0, 0};
    builder.add_floor(quad);
    register_world(builder, 1);
    TestFrame frame;
    const nqr_camera camera = floor_camera();
    const Rgb texture = colour(colour::kOrange);

    draw(frame, camera);
    EXPECT_TRUE(near(floor_pixel(*gl_, camera, 64, 64), lit(texture, 200), 2));

    frame.lightstyles[5] = 0.0f;
    draw(frame, camera);
    EXPECT_EQ(floor_pixel(*gl_, camera, 64, 64), (Rgb{0, 0, 0}));

    frame.lightstyles[5] = 0.5f;
    draw(frame, camera);
    EXPECT_TRUE(near(floor_pixel(*gl_, camera, 64, 64), lit(texture, 200, 0.5), 2));
}

TEST_F(ClassicWorldTest, StylesCombineAndOnlyChangedLightmapsAreRebuilt) {
    BrushBuilder builder;
    const int orange = builder.add_texture("floor", 16, 16, uniform_image(16, colour::kOrange));
    BrushBuilder::Quad a{0, 0, 64, 128, 0, orange};
    a.styles = {0, 3, 255, 255};  // two styles: 60 x style 0 + 40 x style 3
    a.light = {60, 40, 0, 0};
    BrushBuilder::Quad b{64, 0, 128, 128, 0, orange};
    b.styles = {0, 255, 255, 255};
    b.light = {100, 0, 0, 0};
    builder.add_floor(a);
    builder.add_floor(b);
    register_world(builder, 2);
    TestFrame frame;
    const nqr_camera camera = floor_camera();
    const auto& world = *renderer_.models().find(1)->brush;

    draw(frame, camera);
    EXPECT_TRUE(near(floor_pixel(*gl_, camera, 32, 64), lit(colour(colour::kOrange), 100), 2));
    EXPECT_EQ(world.lightmap_rebuilds(), 2);

    draw(frame, camera);  // nothing changed: nothing rebuilt
    EXPECT_EQ(world.lightmap_rebuilds(), 2);

    frame.lightstyles[3] = 2.0f;  // only surface a uses style 3
    draw(frame, camera);
    EXPECT_EQ(world.lightmap_rebuilds(), 3);
    const Rgb texture = colour(colour::kOrange);
    const double stored = std::floor((60.0 + 40.0 * 2.0) * 264.0 / 256.0);
    EXPECT_NEAR(floor_pixel(*gl_, camera, 32, 64).r, texture.r * stored / 255.0 * 2.0, 2.0);
}

// A changed lightmap goes to a texture of the ring (classic::kLightmapRing) that the last frames
// did not draw with: writing a texture the GPU may still be reading makes the driver wait for
// those frames. Every texture of the ring catches up on what changed while it was not current,
// and the world and brush-entity passes of one frame draw with the same texture.
TEST_F(ClassicWorldTest, ChangedLightmapsGoToATextureTheLastFramesDidNotDrawWith) {
    BrushBuilder builder;
    const int orange = builder.add_texture("floor", 16, 16, uniform_image(16, colour::kOrange));
    BrushBuilder::Quad a{0, 0, 64, 128, 0, orange};
    a.styles = {3, 255, 255, 255};
    a.light = {100, 0, 0, 0};
    BrushBuilder::Quad b{64, 0, 128, 128, 0, orange};
    b.styles = {4, 255, 255, 255};
    b.light = {100, 0, 0, 0};
    builder.add_floor(a);  // surface 0: the world, style 3
    builder.add_floor(b);  // surface 1: "*1", style 4
    builder.build();
    nqr_model world_model = builder.model(1, 0, 1);
    nqr_model door_model = builder.model(2, 1, 1, "*1");
    renderer_.register_model(&world_model);
    renderer_.register_model(&door_model);
    nqr_entity door = make_entity(2, glm::mat4(1.0f));
    TestFrame frame;
    frame.brush.push_back(&door);
    const nqr_camera camera = floor_camera();
    const auto& world = *renderer_.models().find(1)->brush;
    const Rgb texture = colour(colour::kOrange);

    std::vector<GLuint> drawn_with;
    auto draw_and_check = [&](float style3, float style4) {
        frame.lightstyles[3] = style3;
        frame.lightstyles[4] = style4;
        gl_->clear({});
        const nqr_frame* f = frame.build(camera, 1, 0.0);
        renderer_.draw_world(f);
        const GLuint world_pass = world.lightmap_texture();
        renderer_.draw_brush_entities(f);
        EXPECT_EQ(world.lightmap_texture(), world_pass) << "the brush pass changed texture";
        drawn_with.push_back(world_pass);
        EXPECT_TRUE(near(floor_pixel(*gl_, camera, 32, 64), lit(texture, 100, style3), 2))
            << "style 3 at " << style3;
        EXPECT_TRUE(near(floor_pixel(*gl_, camera, 96, 64), lit(texture, 100, style4), 2))
            << "style 4 at " << style4;
    };
    draw_and_check(1.0f, 1.0f);
    // Both surfaces change in each of these frames (one in the world pass, one in the brush
    // pass): one new texture per frame, none of the previous kLightmapRing - 1 frames' textures.
    for (int i = 1; i <= 2 * classic::kLightmapRing; ++i) {
        draw_and_check(1.0f + 0.1f * i, 1.0f - 0.05f * i);
        const size_t now = drawn_with.size() - 1;
        for (size_t back = 1; back < classic::kLightmapRing && back <= now; ++back) {
            EXPECT_NE(drawn_with[now], drawn_with[now - back]) << "frame " << now;
        }
    }
    // Nothing changes: the texture stays. Then only style 3 changes, for kLightmapRing frames:
    // each texture that comes round must still hold style 4's last value.
    draw_and_check(2.0f, 0.5f);
    const GLuint settled = drawn_with.back();
    draw_and_check(2.0f, 0.5f);
    EXPECT_EQ(drawn_with.back(), settled);
    for (int i = 1; i <= classic::kLightmapRing; ++i) draw_and_check(2.0f - 0.2f * i, 0.5f);
}

TEST_F(ClassicWorldTest, FullbrightPixelsStayBrightWithoutLight) {
    BrushBuilder builder;
    const int tex =
        builder.add_texture("lamp", 16, 16, make_image(16, 16, [](int x, int) {
                                return x < 8 ? colour::kFullbrightGreen : colour::kOrange;
                            }));
    BrushBuilder::Quad quad{0, 0, 128, 128, 0, tex, 0.125f};
    builder.add_floor(quad);
    register_world(builder, 1);
    TestFrame frame;
    frame.lightstyles[0] = 0.0f;
    const nqr_camera camera = floor_camera();
    draw(frame, camera);
    EXPECT_TRUE(near(floor_pixel(*gl_, camera, 30, 64), colour(colour::kFullbrightGreen), 2))
        << floor_pixel(*gl_, camera, 30, 64);
    EXPECT_EQ(floor_pixel(*gl_, camera, 98, 64), (Rgb{0, 0, 0}));
}

TEST_F(ClassicWorldTest, MapWithoutLightDataIsFullyLit) {
    BrushBuilder builder;
    const int orange = builder.add_texture("floor", 16, 16, uniform_image(16, colour::kOrange));
    builder.add_floor({0, 0, 128, 128, 0, orange});
    register_world(builder, 1, /*with_lighting=*/false);
    TestFrame frame;
    const nqr_camera camera = floor_camera();
    draw(frame, camera);
    const Rgb texture = colour(colour::kOrange);
    const Rgb expected{texture.r * 2, texture.g * 2, texture.b * 2};  // stored 255, doubled
    EXPECT_TRUE(near(floor_pixel(*gl_, camera, 64, 64), expected, 2));
}

TEST_F(ClassicWorldTest, DynamicLightBrightensNearbyLightmapAndGoesAway) {
    BrushBuilder builder;
    const int orange = builder.add_texture("floor", 16, 16, uniform_image(16, colour::kOrange));
    BrushBuilder::Quad quad{0, 0, 128, 128, 0, orange};
    quad.light = {0, 0, 0, 0};
    builder.add_floor(quad);
    register_world(builder, 1);
    TestFrame frame;
    const nqr_camera camera = floor_camera();

    draw(frame, camera);
    EXPECT_EQ(floor_pixel(*gl_, camera, 64, 64), (Rgb{0, 0, 0}));

    // 16 units above the sample at (64, 64): GLQuake adds radius - plane distance - in-plane
    // distance = 100 - 16 - 0 = 84 there; at (0, 0) the in-plane distance 64 + 64/2 is beyond.
    frame.dlights.push_back(make_dlight({64.0f, 64.0f, 16.0f}, 100.0f));
    draw(frame, camera);
    const Rgb texture = colour(colour::kOrange);
    EXPECT_NEAR(floor_pixel(*gl_, camera, 64, 64).r, texture.r * 84.0 / 255.0 * 2.0, 2.0);
    EXPECT_EQ(floor_pixel(*gl_, camera, 1, 1), (Rgb{0, 0, 0}));

    frame.dlights.clear();
    draw(frame, camera);
    EXPECT_EQ(floor_pixel(*gl_, camera, 64, 64), (Rgb{0, 0, 0}));
}

TEST_F(ClassicWorldTest, ColouredDynamicLightTintsTheLightmap) {
    BrushBuilder builder;
    const int grey = builder.add_texture("floor", 16, 16, uniform_image(16, 150));
    BrushBuilder::Quad quad{0, 0, 128, 128, 0, grey};
    quad.light = {0, 0, 0, 0};
    builder.add_floor(quad);
    register_world(builder, 1);
    TestFrame frame;
    frame.dlights.push_back(make_dlight({64.0f, 64.0f, 16.0f}, 100.0f, {1.0f, 0.0f, 0.0f}));
    const nqr_camera camera = floor_camera();
    draw(frame, camera);
    const Rgb centre = floor_pixel(*gl_, camera, 64, 64);
    EXPECT_GT(centre.r, 50);
    EXPECT_EQ(centre.g, 0);
    EXPECT_EQ(centre.b, 0);
}

TEST_F(ClassicWorldTest, AnimatedTexturesAdvanceEveryFifthOfASecond) {
    BrushBuilder builder;
    const int red = builder.add_texture("+0anim", 16, 16, uniform_image(16, colour::kRed));
    const int blue = builder.add_texture("+1anim", 16, 16, uniform_image(16, colour::kBlue));
    const int teal = builder.add_texture("+aanim", 16, 16, uniform_image(16, colour::kTeal));
    builder.set_animation(red, {red, blue}, {teal});
    builder.set_animation(blue, {red, blue}, {teal});
    builder.add_floor({0, 0, 128, 128, 0, red});
    register_world(builder, 1);
    TestFrame frame;
    const nqr_camera camera = floor_camera();
    const Rgb lit_red = lit(colour(colour::kRed), 128), lit_blue = lit(colour(colour::kBlue), 128);

    draw(frame, camera, 0.05);
    EXPECT_TRUE(near(floor_pixel(*gl_, camera, 64, 64), lit_red, 2));
    draw(frame, camera, 0.25);
    EXPECT_TRUE(near(floor_pixel(*gl_, camera, 64, 64), lit_blue, 2));
    draw(frame, camera, 0.45);
    EXPECT_TRUE(near(floor_pixel(*gl_, camera, 64, 64), lit_red, 2));
}

TEST_F(ClassicWorldTest, BrushEntityIsPlacedByItsMatrixAndUsesAlternateAnimation) {
    BrushBuilder builder;
    const int grey = builder.add_texture("floor", 16, 16, uniform_image(16, 60));
    const int red = builder.add_texture("+0door", 16, 16, uniform_image(16, colour::kRed));
    const int teal = builder.add_texture("+adoor", 16, 16, uniform_image(16, colour::kTeal));
    builder.set_animation(red, {red}, {teal});
    builder.add_floor({0, 0, 128, 128, 0, grey});  // surface 0: the world
    builder.add_floor({0, 0, 32, 32, 0, red});     // surface 1: submodel "*1"
    builder.build();
    nqr_model world = builder.model(1, 0, 1);
    nqr_model door = builder.model(2, 1, 1, "*1");
    renderer_.register_model(&world);
    renderer_.register_model(&door);
    EXPECT_EQ(renderer_.models().brush_geometry_count(), 1u);  // shared by world and "*1"

    nqr_entity entity = make_entity(2, glm::translate(glm::mat4(1.0f), {64.0f, 64.0f, 8.0f}));
    TestFrame frame;
    frame.brush.push_back(&entity);
    const nqr_camera camera = floor_camera();
    draw(frame, camera);
    const Rgb lit_grey = lit({60, 60, 60}, 128);
    // The door sits at (64..96, 64..96), 8 units up; its own placement (0..32) shows floor.
    EXPECT_TRUE(near(floor_pixel(*gl_, camera, 80, 80), lit(colour(colour::kRed), 128), 3))
        << floor_pixel(*gl_, camera, 80, 80);
    EXPECT_TRUE(near(floor_pixel(*gl_, camera, 16, 16), lit_grey, 2));

    entity.frame = 1;  // triggered: the alternate chain
    draw(frame, camera);
    EXPECT_TRUE(near(floor_pixel(*gl_, camera, 80, 80), lit(colour(colour::kTeal), 128), 3));
}

TEST_F(ClassicWorldTest, OnlyVisibleSurfacesAreDrawn) {
    BrushBuilder builder;
    const int orange = builder.add_texture("floor", 16, 16, uniform_image(16, colour::kOrange));
    builder.add_floor({0, 0, 64, 128, 0, orange});
    builder.add_floor({64, 0, 128, 128, 0, orange});
    register_world(builder, 2);
    TestFrame frame;
    frame.use_visible_list = true;
    frame.visible = {1};
    const nqr_camera camera = floor_camera();
    const Rgb background{10, 20, 30};
    draw(frame, camera, 0.0, background);
    EXPECT_EQ(floor_pixel(*gl_, camera, 32, 64), background);
    EXPECT_TRUE(near(floor_pixel(*gl_, camera, 96, 64), lit(colour(colour::kOrange), 128), 2));
}

std::vector<uint8_t> sky_image(bool striped_front) {
    // 256 x 128: right half the back layer (blue), left half the front layer (0 = clear).
    return make_image(256, 128, [&](int x, int) -> uint8_t {
        if (x >= 128) return colour::kBlue;
        return striped_front && (x % 32) < 16 ? colour::kRed : colour::kSkyTransparent;
    });
}

TEST_F(ClassicWorldTest, SkyShowsBackLayerThroughClearFrontLayer) {
    BrushBuilder builder;
    const int sky = builder.add_texture("sky1", 256, 128, sky_image(false), NQR_TEXTURE_SKY);
    BrushBuilder::Quad quad{0, 0, 128, 128, 0, sky};
    quad.flags = NQR_SURFACE_SKY;
    builder.add_floor(quad);
    register_world(builder, 1);
    TestFrame frame;
    const nqr_camera camera = floor_camera();
    draw(frame, camera);
    // Unlit: the palette colour itself, everywhere on the surface.
    for (float x : {10.0f, 64.0f, 118.0f}) {
        EXPECT_TRUE(near(floor_pixel(*gl_, camera, x, x), colour(colour::kBlue), 2));
    }
}

TEST_F(ClassicWorldTest, SkyFrontLayerCoversBackAndScrollsWithTime) {
    BrushBuilder builder;
    const int sky = builder.add_texture("sky1", 256, 128, sky_image(true), NQR_TEXTURE_SKY);
    BrushBuilder::Quad quad{0, 0, 128, 128, 0, sky};
    quad.flags = NQR_SURFACE_SKY;
    builder.add_floor(quad);
    register_world(builder, 1);
    TestFrame frame;
    const nqr_camera camera = floor_camera();
    draw(frame, camera, 0.0);
    const std::vector<Rgb> at_zero = gl_->pixels();
    int red = 0, blue = 0;
    for (const Rgb& p : at_zero) {
        red += near(p, colour(colour::kRed), 6);
        blue += near(p, colour(colour::kBlue), 6);
    }
    EXPECT_GT(red, 1000);   // front stripes
    EXPECT_GT(blue, 1000);  // back layer between them

    draw(frame, camera, 0.5);  // the front layer moved 8 units, the back 4
    const std::vector<Rgb> later = gl_->pixels();
    int changed = 0;
    for (size_t i = 0; i < later.size(); ++i) changed += !near(later[i], at_zero[i], 6);
    EXPECT_GT(changed, 1000);
}

TEST_F(ClassicWorldTest, LiquidIsUnlitWarpedAndKeepsItsMeanColour) {
    BrushBuilder builder;
    // 64 x 64 vertical stripes 8 texels wide, red and teal; one texel per unit. The same image
    // as a plain lit texture (surface 0) is the unwarped control; surface 1 is the liquid.
    auto stripe = [](int s) { return ((s % 16) + 16) % 16 < 8; };
    auto stripes = [&] {
        return make_image(64, 64,
                          [&](int x, int) { return stripe(x) ? colour::kRed : colour::kTeal; });
    };
    const int plain = builder.add_texture("stripes", 64, 64, stripes());
    const int water = builder.add_texture("*water", 64, 64, stripes(), NQR_TEXTURE_LIQUID);
    builder.add_floor({0, 0, 128, 128, 0, plain});
    BrushBuilder::Quad liquid{0, 0, 128, 128, 0, water};
    liquid.flags = NQR_SURFACE_LIQUID;
    builder.add_floor(liquid);
    register_world(builder, 2);
    TestFrame frame;
    frame.use_visible_list = true;
    const nqr_camera camera = floor_camera();
    const Rgb red = colour(colour::kRed), teal = colour(colour::kTeal);

    struct Stats {
        int matches_unwarped = 0, total = 0;
        double mean[3] = {0, 0, 0};
    };
    auto measure = [&] {
        Stats stats;
        for (int y = 4; y < 124; ++y) {  // pixel row y shows world x = y + 0.5
            for (int px = 4; px < 124; ++px) {
                const Rgb p = gl_->pixel(px, y);
                const Rgb unwarped = stripe(y) ? red : teal;
                stats.matches_unwarped += near(p, unwarped, 10);
                stats.mean[0] += p.r;
                stats.mean[1] += p.g;
                stats.mean[2] += p.b;
                ++stats.total;
            }
        }
        for (double& m : stats.mean) m /= stats.total;
        return stats;
    };

    frame.visible = {0};  // control: lit at sample 128 draws the texture at x 1.035
    draw(frame, camera, 1.0);
    const Stats control = measure();
    EXPECT_GT(control.matches_unwarped, control.total * 0.9);

    frame.visible = {1};
    draw(frame, camera, 1.0);
    const Stats warped = measure();
    // The stripes wander by up to 8 texels, so far fewer pixels sit where they would unwarped.
    EXPECT_LT(warped.matches_unwarped, warped.total * 0.6) << warped.matches_unwarped;
    // Unlit and unshifted on average: the mean is the texture's own mean colour.
    const double expected[3] = {(red.r + teal.r) / 2.0, (red.g + teal.g) / 2.0,
                                (red.b + teal.b) / 2.0};
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(warped.mean[c], expected[c], 8.0) << c;
}

TEST_F(ClassicWorldTest, BackFacesAreCulled) {
    BrushBuilder builder;
    const int orange = builder.add_texture("floor", 16, 16, uniform_image(16, colour::kOrange));
    builder.add_floor({0, 0, 128, 128, 0, orange});
    register_world(builder, 1);
    TestFrame frame;
    const Rgb background{10, 20, 30};
    // From below, looking up at the floor's back.
    const nqr_camera below = make_camera({64.0f, 64.0f, -64.0f}, {-90.0f, 0.0f, 0.0f});
    draw(frame, below, 0.0, background);
    EXPECT_EQ(coverage(gl_->pixels(), background, 0).count, 0);
    draw(frame, floor_camera(), 0.0, background);
    EXPECT_EQ(coverage(gl_->pixels(), background, 0).count, kSize * kSize);
}

TEST_F(ClassicWorldTest, LightmapsArePackedIntoSharedAtlasPages) {
    BrushBuilder builder;
    const int orange = builder.add_texture("floor", 16, 16, uniform_image(16, colour::kOrange));
    for (int i = 0; i < 40; ++i) {  // 40 surfaces of 9 x 9 samples: one 512 x 512 page
        builder.add_floor(
            {static_cast<float>(i * 3), 0, static_cast<float>(i * 3 + 128), 128, 0, orange});
    }
    register_world(builder, 40);
    EXPECT_EQ(renderer_.models().find(1)->brush->lightmap_pages(), 1);
}

TEST_F(ClassicWorldTest, BadModelIsSkippedWithALogLine) {
    captured_log().clear();
    nqr_model model{};
    model.size = sizeof(nqr_model);
    model.id = 7;
    model.kind = NQR_MODEL_BRUSH;
    model.name = "maps/broken.bsp";
    nqr_brush_model brush{};
    brush.size = 8;  // an older, shorter struct than this build knows
    model.brush = &brush;
    renderer_.register_model(&model);
    EXPECT_EQ(renderer_.models().find(7), nullptr);
    ASSERT_FALSE(captured_log().empty());
    EXPECT_NE(captured_log().back().find("maps/broken.bsp"), std::string::npos);
}

}  // namespace
}  // namespace nq::npr::test

// Batches keep the order surfaces were added in (the engine lists them front to back), within a
// texture and across textures; a repeat is ignored.
TEST(ClassicSurfaceBatches, KeepTheOrderSurfacesCameIn) {
    using nq::npr::classic::BrushSurfaceMesh;
    using nq::npr::classic::SurfaceBatches;
    std::vector<BrushSurfaceMesh> surfaces(8);
    for (uint32_t s = 0; s < surfaces.size(); ++s) {
        surfaces[s].first_index = 100 * s;
        surfaces[s].index_count = 3 + s;
    }
    SurfaceBatches batches;
    batches.resize(surfaces.size(), 2);
    for (int frame = 0; frame < 2; ++frame) {  // the second frame reuses the arrays
        batches.begin();
        const uint32_t added[][2] = {{5, 1}, {2, 0}, {7, 1}, {5, 1}, {3, 0}, {1, 1}};
        for (const auto& [surface, slot] : added) batches.add(surface, slot);
        batches.finish(surfaces);
        ASSERT_EQ(batches.batches().size(), 2u);
        const nq::npr::classic::SurfaceBatch first = batches.batches()[0];
        const nq::npr::classic::SurfaceBatch second = batches.batches()[1];
        EXPECT_EQ(first.texture_slot, 1u);
        EXPECT_EQ(second.texture_slot, 0u);
        auto surface_at = [&](uint32_t i) {
            return static_cast<uint32_t>(reinterpret_cast<uintptr_t>(batches.offsets()[i]) / 400);
        };
        ASSERT_EQ(first.count, 3u);
        EXPECT_EQ(surface_at(first.first), 5u);
        EXPECT_EQ(surface_at(first.first + 1), 7u);
        EXPECT_EQ(surface_at(first.first + 2), 1u);
        EXPECT_EQ(batches.counts()[first.first + 2], 4);
        ASSERT_EQ(second.count, 2u);
        EXPECT_EQ(surface_at(second.first), 2u);
        EXPECT_EQ(surface_at(second.first + 1), 3u);
    }
}

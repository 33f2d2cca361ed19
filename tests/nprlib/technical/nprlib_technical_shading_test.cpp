// The technical style's face shading of alias models (nprlib/technical/alias_face_drawer): Gooch
// 98 cool-to-warm tones, splash-back, the skin-average/texel blend, metal bands and classic
// lighting, each checked on real pixels of synthetic models (Mesa llvmpipe) against the formula
// recomputed here; plus the classic drawer's duties (fullbright, holes, alpha, normals).
#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include "abi/frame_view.h"
#include "classic/alias_model_gpu.h"
#include "classic/classic_pass.h"
#include "support/nprlib_test_sphere.h"
#include "support/nprlib_test_support.h"
#include "technical/alias_face_drawer.h"
#include "technical/shading_model.h"
#include "technical/skin_tones.h"
#include "technical/technical_settings.h"

namespace nq::npr::test {
namespace {

using technical::AliasFaceDrawer;
using technical::ShadingMode;
using technical::ShadingSettings;

constexpr uint8_t kGrey = 150;  // palette index of (150, 150, 150)
const Rgb kBackground{10, 20, 30};

// ------------------------------------------------------------------ expected colours

glm::vec3 palette_rgb(int index) {
    const Rgb c = palette_colour(make_test_palette(), index);
    return glm::vec3(c.r, c.g, c.b) / 255.0f;
}

Rgb to_rgb(glm::vec3 c) {
    c = glm::clamp(c, 0.0f, 1.0f) * 255.0f;
    return {static_cast<int>(std::lround(c.r)), static_cast<int>(std::lround(c.g)),
            static_cast<int>(std::lround(c.b))};
}

float splashback_factor(float n_dot_l, const ShadingSettings& s) {
    if (!s.splashback) return 1.0f;
    const float a = s.splashback_alpha;
    return std::pow(a * std::abs(n_dot_l) + (1.0f - a), s.splashback_p);
}

// Gooch 98 with the warm tone on the side facing the light.
glm::vec3 gooch(glm::vec3 kd, float n_dot_l, const ShadingSettings& s) {
    const glm::vec3 cool = glm::vec3(0.0f, 0.0f, s.blue) + s.alpha * kd;
    const glm::vec3 warm = glm::vec3(s.yellow, s.yellow, 0.0f) + s.beta * kd;
    const float warmth = (1.0f + n_dot_l) / 2.0f;  // 1 facing the light, 0 facing away
    const glm::vec3 tone = warmth * warm + (1.0f - warmth) * cool;
    return glm::clamp(tone * splashback_factor(n_dot_l, s), 0.0f, 1.0f);
}

ShadingSettings gooch_settings(bool splashback) {
    ShadingSettings s;
    s.mode = ShadingMode::gooch;
    s.splashback = splashback;
    return s;
}

// ------------------------------------------------------------------ fixture

// From (-60, 0, 0) looking along +X: the sphere's -X pole is at the centre of the image.
nqr_camera front_camera() {
    return make_camera({-60.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 0.0f});
}

class TechnicalShadingTest : public GlSuiteTest<TechnicalShadingTest> {
  protected:
    void SetUp() override {
        GlSuiteTest::SetUp();
        if (HasFatalFailure()) return;
        std::string error;
        ASSERT_TRUE(drawer_.init(&tracker_, error)) << error;
        entity_ = make_entity(1);
        entity_.light = &light_;
    }

    void TearDown() override {
        gpu_.reset();
        drawer_.reset();
        EXPECT_EQ(tracker_.total_live(), 0);
    }

    // builder_ outlives the upload: the GPU model keeps pointing at its nqr_alias_model.
    void upload() {
        std::string error;
        gpu_ = classic::AliasModelGpu::create(&tracker_, *builder_.build(), palette_.data(), error);
        ASSERT_TRUE(gpu_) << error;
    }

    void upload_sphere(uint8_t skin_index) {
        make_sphere(builder_, {4, 4});
        builder_.skin.assign(64, skin_index);
        upload();
    }

    // Light from direction `toward_light` (world, need not be unit).
    void light_from(glm::vec3 toward_light) {
        const glm::vec3 l = glm::normalize(toward_light);
        std::copy_n(&l.x, 3, light_.direction);
    }

    void draw(const ShadingSettings& settings, const nqr_camera& camera = front_camera()) {
        gl_->clear(kBackground);
        npr::FrameView view;
        ASSERT_TRUE(npr::read_frame_view(frame_.build(camera, 0), view));
        const classic::SkinImageGpu* image = gpu_->skin_image(0, 0);
        ASSERT_NE(image, nullptr);
        classic::begin_classic_pass();
        const glm::vec3 kd =
            technical::sample_skin(gpu_->model(), gpu_->skin_pixels(0, 0), entity_, palette_.data())
                .average;
        drawer_.draw_entity(view, entity_, *gpu_, image->base.id(),
                            image->fullbright ? image->fullbright.id() : 0, kd, settings);
        EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    }

    // The pixel showing the sphere's near pole (normal -X).
    Rgb pole_pixel() const {
        const glm::vec2 p = project(front_camera(), {-kSphereRadius, 0.0f, 0.0f});
        return gl_->pixel(static_cast<int>(p.x), static_cast<int>(p.y));
    }

    // The pole pixel with the light at angle n.l = cos(angle) to the pole's normal (-X).
    Rgb pole_lit_at(float n_dot_l, const ShadingSettings& settings) {
        const float sine = std::sqrt(std::max(0.0f, 1.0f - n_dot_l * n_dot_l));
        light_from({-n_dot_l, 0.0f, sine});
        draw(settings);
        return pole_pixel();
    }

    std::array<uint8_t, 768> palette_ = make_test_palette();
    gl::ObjectTracker tracker_;
    AliasFaceDrawer drawer_;
    AliasBuilder builder_;
    std::unique_ptr<classic::AliasModelGpu> gpu_;
    nqr_entity entity_{};
    nqr_entity_light light_ = make_light();  // entity_.light points here
    TestFrame frame_;
};

constexpr int kTolerance = 4;

#define EXPECT_COLOUR(actual, expected)                                                 \
    EXPECT_TRUE(near((actual), (expected), kTolerance)) << "drawn " << (actual) << ", " \
                                                        << "expected " << (expected)

// ------------------------------------------------------------------ Gooch 98

TEST_F(TechnicalShadingTest, GoochIsWarmTowardTheLightAndCoolAway) {
    upload_sphere(kGrey);
    const ShadingSettings s = gooch_settings(false);
    const glm::vec3 kd = palette_rgb(kGrey);
    const Rgb lit = pole_lit_at(1.0f, s);
    const Rgb side = pole_lit_at(0.0f, s);
    const Rgb away = pole_lit_at(-1.0f, s);
    EXPECT_COLOUR(lit, to_rgb(gooch(kd, 1.0f, s)));
    EXPECT_COLOUR(side, to_rgb(gooch(kd, 0.0f, s)));
    EXPECT_COLOUR(away, to_rgb(gooch(kd, -1.0f, s)));
    EXPECT_GT(lit.r, lit.b + 60);    // yellowish where lit
    EXPECT_GT(away.b, away.r + 60);  // bluish where not
}

TEST_F(TechnicalShadingTest, GoochFollowsTheLightAroundTheModel) {
    // One picture, light from above-left-front: every pixel of the sphere is checked against
    // the formula with its own normal (the sphere's, from the pixel's ray), inner pixels only.
    upload_sphere(kGrey);
    const ShadingSettings s = gooch_settings(true);
    const glm::vec3 l = glm::normalize(glm::vec3(-1.0f, 1.0f, 1.0f));
    light_from(l);
    draw(s);
    const std::vector<Rgb> image = gl_->pixels();
    const glm::vec3 kd = palette_rgb(kGrey);
    const glm::vec3 eye(-60.0f, 0.0f, 0.0f);
    int checked = 0, wrong = 0;
    for (int y = 0; y < kSize; y += 3) {
        for (int x = 0; x < kSize; x += 3) {
            const std::optional<glm::vec3> hit = sphere_normal_at_pixel(x, y, eye);
            if (!hit) continue;
            const glm::vec3 n = *hit;
            if (glm::dot(n, glm::normalize(eye - n * kSphereRadius)) < 0.5f) continue;  // outline
            ++checked;
            const Rgb expected = to_rgb(gooch(kd, glm::dot(n, l), s));
            wrong += !near(image[y * kSize + x], expected, 8);
        }
    }
    EXPECT_GT(checked, 150);
    EXPECT_LE(wrong, checked / 50) << wrong << " of " << checked;
}

TEST_F(TechnicalShadingTest, SplashBackDarkensTheTerminatorOnly) {
    upload_sphere(kGrey);
    const ShadingSettings off = gooch_settings(false), on = gooch_settings(true);
    const glm::vec3 kd = palette_rgb(kGrey);
    const Rgb side_off = pole_lit_at(0.0f, off), side_on = pole_lit_at(0.0f, on);
    EXPECT_COLOUR(side_on, to_rgb(gooch(kd, 0.0f, off) * splashback_factor(0.0f, on)));
    EXPECT_LT(brightness(side_on), brightness(side_off) * 0.45);
    // Facing the light or away from it, |cos| = 1: splash-back changes nothing.
    EXPECT_COLOUR(pole_lit_at(1.0f, on), pole_lit_at(1.0f, off));
    EXPECT_COLOUR(pole_lit_at(-1.0f, on), pole_lit_at(-1.0f, off));
    // Halfway, the factor recomputed here.
    EXPECT_COLOUR(pole_lit_at(-0.5f, on), to_rgb(gooch(kd, -0.5f, on)));
}

// ------------------------------------------------------------------ k_d

TEST_F(TechnicalShadingTest, TextureBlendGoesFromSkinAverageToTexel) {
    // Left half red, right half blue; every vertex samples texel (2, 4): red.
    AliasBuilder& b = builder_;
    make_sphere(b, {2, 4});
    b.skin = make_image(8, 8, [](int x, int) { return x < 4 ? colour::kRed : colour::kBlue; });
    upload();
    const glm::vec3 red = palette_rgb(colour::kRed), blue = palette_rgb(colour::kBlue);
    const glm::vec3 average = (red + blue) / 2.0f;
    for (float blend : {0.0f, 0.5f, 1.0f}) {
        ShadingSettings s = gooch_settings(false);
        s.texture_blend = blend;
        const glm::vec3 kd = average + blend * (red - average);
        EXPECT_COLOUR(pole_lit_at(1.0f, s), to_rgb(gooch(kd, 1.0f, s))) << "blend " << blend;
    }
}

// ------------------------------------------------------------------ metal and classic

TEST_F(TechnicalShadingTest, MetalShowsBandsAcrossTheHeight) {
    // A tall box (16 x 16 x 96) seen face on; lit from behind so only the bands remain.
    AliasBuilder& b = builder_;
    b.add_box_pose({0, 0, 0}, {16, 16, 96});
    b.origin = {-8.0f, -8.0f, -48.0f};
    b.skin.assign(64, kGrey);
    upload();
    light_from({1.0f, 0.0f, 0.0f});
    ShadingSettings s;
    s.mode = ShadingMode::metal;
    s.splashback = false;
    const nqr_camera camera = make_camera({-80.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 0.0f});
    draw(s, camera);
    const glm::vec3 kd = palette_rgb(kGrey);
    int darkest = 255 * 3, brightest = 0;
    for (int y = 24; y < kSize - 24; ++y) {
        // The face x = -8 is 72 units from the eye; fov 90: height = ndc_y * 72.
        const float height = ((y + 0.5f) / (kSize / 2.0f) - 1.0f) * 72.0f;
        const float band = 0.5f + 0.5f * std::sin(height * s.metal_bands * 2.0f *
                                                  std::numbers::pi_v<float> / 100.0f);
        const Rgb pixel = gl_->pixel(kSize / 2, y);
        EXPECT_COLOUR(pixel, to_rgb(kd * (0.55f + 0.6f * band))) << " at height " << height;
        darkest = std::min(darkest, brightness(pixel));
        brightest = std::max(brightest, brightness(pixel));
    }
    EXPECT_GT(brightest - darkest, 200);  // about 0.6 * 150 per channel
}

TEST_F(TechnicalShadingTest, ClassicModeIsAmbientPlusDirectional) {
    upload_sphere(kGrey);
    light_.ambient = 0.3f;
    light_.directional = 0.5f;
    light_.color[1] = 0.8f;
    light_.color[2] = 0.6f;
    ShadingSettings s;  // splash-back on: classic ignores it
    s.mode = ShadingMode::classic;
    const glm::vec3 kd = palette_rgb(kGrey), tint(1.0f, 0.8f, 0.6f);
    EXPECT_COLOUR(pole_lit_at(1.0f, s), to_rgb(kd * 0.8f * tint));
    EXPECT_COLOUR(pole_lit_at(0.5f, s), to_rgb(kd * 0.55f * tint));
    EXPECT_COLOUR(pole_lit_at(0.0f, s), to_rgb(kd * 0.3f * tint));
    EXPECT_COLOUR(pole_lit_at(-1.0f, s), to_rgb(kd * 0.3f * tint));
}

// ------------------------------------------------------------------ as the classic drawer

TEST_F(TechnicalShadingTest, FullbrightSkinPixelsAreAddedUnlit) {
    upload_sphere(colour::kFullbrightGreen);  // the lit skin is black there: k_d = 0
    const ShadingSettings s = gooch_settings(false);
    const glm::vec3 expected = gooch(glm::vec3(0.0f), -1.0f, s) + palette_rgb(240);
    EXPECT_COLOUR(pole_lit_at(-1.0f, s), to_rgb(expected));
}

TEST_F(TechnicalShadingTest, HoleyModelsCutOutTransparentTexels) {
    AliasBuilder& b = builder_;
    make_sphere(b, {4, 4});
    b.skin.assign(64, colour::kTransparent);
    b.flags = classic::kAliasFlagHoley;
    upload();
    draw(gooch_settings(true));
    EXPECT_EQ(pole_pixel(), kBackground);
}

TEST_F(TechnicalShadingTest, TranslucentEntityBlendsOverTheBackground) {
    upload_sphere(kGrey);
    const ShadingSettings s = gooch_settings(false);
    entity_.alpha = 0.5f;
    const glm::vec3 background = glm::vec3(kBackground.r, kBackground.g, kBackground.b) / 255.f;
    const glm::vec3 shaded = gooch(palette_rgb(kGrey), 1.0f, s);
    EXPECT_COLOUR(pole_lit_at(1.0f, s), to_rgb(0.5f * shaded + 0.5f * background));
}

TEST_F(TechnicalShadingTest, OnlyTheOutsideIsDrawnAndStateIsRestored) {
    // From inside the sphere every face is seen from behind: all culled.
    upload_sphere(kGrey);
    draw(gooch_settings(true), make_camera({0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 0.0f}));
    for (const Rgb& p : gl_->pixels()) ASSERT_EQ(p, kBackground);
    EXPECT_FALSE(glIsEnabled(GL_CULL_FACE));
    EXPECT_FALSE(glIsEnabled(GL_BLEND));
    EXPECT_FALSE(glIsEnabled(GL_STENCIL_TEST));
    GLint value = -1;
    glGetIntegerv(GL_CURRENT_PROGRAM, &value);
    EXPECT_EQ(value, 0);
    glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &value);
    EXPECT_EQ(value, 0);
    GLboolean depth_writes = GL_FALSE;
    glGetBooleanv(GL_DEPTH_WRITEMASK, &depth_writes);
    EXPECT_TRUE(depth_writes);
}

TEST_F(TechnicalShadingTest, WritesViewSpaceNormalsToLocationOne) {
    upload_sphere(kGrey);
    GLuint normals = 0;
    glGenTextures(1, &normals);
    glBindTexture(GL_TEXTURE_2D, normals);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, kSize, kSize, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    gl_->bind();
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, normals, 0);
    const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glDrawBuffers(2, buffers);
    draw(gooch_settings(true));
    glReadBuffer(GL_COLOR_ATTACHMENT1);
    const Rgb encoded = pole_pixel();
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glDrawBuffers(1, buffers);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, 0, 0);
    glDeleteTextures(1, &normals);
    // The pole faces the eye: view-space normal (0, 0, 1), stored as n * 0.5 + 0.5.
    EXPECT_TRUE(near(encoded, Rgb{128, 128, 255}, 3)) << encoded;
}

}  // namespace
}  // namespace nq::npr::test

namespace nq::npr::test {
namespace {

// ------------------------------------------------------------------ the CPU twin (edge ends)

// technical::technical_shade on the CPU gives what the faces show per pixel, mode by mode.
TEST_F(TechnicalShadingTest, CpuTonesMatchThePixelsOfTheFaces) {
    upload_sphere(kGrey);
    light_.size = sizeof(nqr_entity_light);
    light_.ambient = 0.4f;
    light_.directional = 0.5f;
    std::fill_n(light_.color, 3, 1.0f);
    const glm::vec3 kd = palette_rgb(kGrey);
    for (const ShadingMode mode :
         {ShadingMode::classic, ShadingMode::gooch, ShadingMode::metal, ShadingMode::object_id}) {
        for (const bool splashback : {false, true}) {
            ShadingSettings s;
            s.mode = mode;
            s.splashback = splashback;
            s.metal_bands = 0.0f;  // the pole pixel is not exactly at height 0
            for (const float n_dot_l : {-1.0f, -0.5f, 0.0f, 0.5f, 1.0f}) {
                const Rgb drawn = pole_lit_at(n_dot_l, s);
                // The pole: normal -X, height 0.
                const glm::vec3 cpu = technical::technical_shade(s, technical::tone_light(entity_),
                                                                 kd, {-1.0f, 0.0f, 0.0f}, 0.0f);
                EXPECT_COLOUR(drawn, to_rgb(cpu))
                    << "mode " << static_cast<int>(mode) << " splash-back " << splashback << " n.l "
                    << n_dot_l;
            }
        }
    }
}

TEST(TechnicalShadingModel, GoochOnTheCpuIsTheFormula) {
    technical::ToneLight light;
    light.direction = {0.0f, 0.0f, 1.0f};
    const glm::vec3 kd(0.2f, 0.5f, 0.7f);
    for (const bool splashback : {false, true}) {
        const ShadingSettings s = gooch_settings(splashback);
        for (const float c : {-1.0f, -0.3f, 0.0f, 0.6f, 1.0f}) {
            const glm::vec3 n(std::sqrt(1.0f - c * c), 0.0f, c);
            const glm::vec3 cpu = technical::technical_shade(s, light, kd, n, 0.0f);
            const glm::vec3 expected = gooch(kd, c, s);
            EXPECT_NEAR(glm::distance(cpu, expected), 0.0f, 1e-5f) << "n.l " << c;
        }
    }
}

// ------------------------------------------------------------------ k_d on the CPU

class SkinTonesTest : public ::testing::Test {
  protected:
    const nqr_alias_model& model_with_skin(std::vector<uint8_t> skin, uint32_t flags = 0) {
        make_sphere(builder_, {2, 4});
        builder_.skin = std::move(skin);
        builder_.flags = flags;
        return *builder_.build();
    }
    static glm::vec3 mean_of(std::initializer_list<glm::vec3> colours) {
        glm::vec3 sum(0.0f);
        for (const glm::vec3& c : colours) sum += c;
        return sum / static_cast<float>(colours.size());
    }
    AliasBuilder builder_;
    std::array<uint8_t, 768> palette_ = make_test_palette();
};

TEST_F(SkinTonesTest, AverageIsTheMeanOfTheLitSkin) {
    // Four quarters: red, blue, grey and a fullbright colour, which the lit skin holds as black.
    const nqr_alias_model& model = model_with_skin(make_image(8, 8, [](int x, int y) {
        if (y < 4) return x < 4 ? colour::kRed : colour::kBlue;
        return x < 4 ? kGrey : uint8_t{240};
    }));
    nqr_entity entity{};
    technical::SkinTones tones;
    tones.build(model);
    const technical::SkinSample sample =
        tones.sample(model, model.skins[0].images[0], entity, palette_.data());
    const glm::vec3 expected = mean_of({palette_rgb(colour::kRed), palette_rgb(colour::kBlue),
                                        palette_rgb(kGrey), glm::vec3(0.0f)});
    EXPECT_NEAR(glm::distance(sample.average, expected), 0.0f, 1e-5f);
    // The one-off form counts the same.
    const technical::SkinSample once =
        technical::sample_skin(model, model.skins[0].images[0], entity, palette_.data());
    EXPECT_NEAR(glm::distance(once.average, expected), 0.0f, 1e-5f);
}

TEST_F(SkinTonesTest, PlayerColoursTranslateTheAverageAndTheTexels) {
    // Half shirt-range pixels (index 16 + 3), half grey; shirt colour 4 moves them to 4 * 16 + 3.
    const nqr_alias_model& model = model_with_skin(make_image(
        8, 8, [](int x, int) { return x < 4 ? uint8_t{colour::kShirtBase + 3} : kGrey; }));
    nqr_entity entity{};
    entity.has_translation = 1;
    entity.top_color = 4;
    technical::SkinTones tones;
    tones.build(model);
    const technical::SkinSample sample =
        tones.sample(model, model.skins[0].images[0], entity, palette_.data());
    const glm::vec3 shirt = palette_rgb(4 * 16 + 3);
    EXPECT_NEAR(glm::distance(sample.average, mean_of({shirt, palette_rgb(kGrey)})), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::distance(sample.kd(1, 1, 1.0f), shirt), 0.0f, 1e-5f);  // texel (1, 1)
    EXPECT_NEAR(glm::distance(sample.kd(1, 1, 0.0f), sample.average), 0.0f, 1e-6f);
}

TEST_F(SkinTonesTest, HoleyModelsLeaveTheirTransparentIndexOut) {
    const nqr_alias_model& model = model_with_skin(
        make_image(8, 8, [](int x, int) { return x < 4 ? uint8_t{255} : colour::kRed; }),
        classic::kAliasFlagHoley);
    nqr_entity entity{};
    const technical::SkinSample sample =
        technical::sample_skin(model, model.skins[0].images[0], entity, palette_.data());
    EXPECT_NEAR(glm::distance(sample.average, palette_rgb(colour::kRed)), 0.0f, 1e-5f);
}

}  // namespace
}  // namespace nq::npr::test

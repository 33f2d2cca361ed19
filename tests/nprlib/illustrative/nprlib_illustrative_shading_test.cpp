// The illustrative style's model shading (nprlib/illustrative/alias_shading_drawer, the paper's
// equations 1 and 2 in illustrative_glsl.h) on real pixels of a synthetic sphere (Mesa
// llvmpipe), each term checked against the formula recomputed here: the warped half-Lambert
// diffuse, the ambient cube, Phong with Source's Fresnel ranges, the per-light rim and the
// dedicated rim, ramp swaps, team-colour saturation and the normals' plumbing.
#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <vector>

#include "abi/frame_view.h"
#include "classic/alias_model_gpu.h"
#include "classic/classic_pass.h"
#include "gl/texture_upload.h"
#include "illustrative/alias_shading_drawer.h"
#include "illustrative/illustrative_model.h"
#include "illustrative/illustrative_models.h"
#include "illustrative/warp_ramp.h"
#include "support/nprlib_test_sphere.h"
#include "support/nprlib_test_support.h"

namespace nq::npr::test {
namespace {

using illustrative::AliasShadingDrawer;
using illustrative::AliasShadingTextures;
using illustrative::IllustrativeSettings;
using illustrative::MaterialParams;
using illustrative::ShowTerm;

constexpr uint8_t kGrey = 150;  // palette index of (150, 150, 150)
const Rgb kBackground{0, 0, 0};
const glm::vec3 kEye(-60.0f, 0.0f, 0.0f);

// A ramp texture of 256 texels, texel i = f(i / 255) (RGB 0..1).
std::vector<uint8_t> ramp_texels(const std::function<glm::vec3(float)>& f) {
    std::vector<uint8_t> rgba(256 * 4, 255);
    for (int i = 0; i < 256; ++i) {
        const glm::vec3 c = glm::clamp(f(i / 255.0f), 0.0f, 1.0f);
        for (int k = 0; k < 3; ++k) rgba[i * 4 + k] = static_cast<uint8_t>(std::lround(c[k] * 255));
    }
    return rgba;
}

// Ramp A: red rises, blue falls, green flat. Ramp B: all channels rise.
glm::vec3 ramp_a(float x) {
    return {0.5f * x, 0.25f, 0.5f * (1.0f - x)};
}
glm::vec3 ramp_b(float x) {
    return glm::vec3(0.45f * x);
}

// What linear filtering of a 256-texel ramp returns at coordinate x: texel centres at
// (i + 0.5) / 256, clamped at both ends.
glm::vec3 sample_ramp(const std::function<glm::vec3(float)>& f, float x) {
    const float texel = std::clamp(x * 256.0f - 0.5f, 0.0f, 255.0f);
    const int i0 = static_cast<int>(std::floor(texel));
    const int i1 = std::min(i0 + 1, 255);
    const float t = texel - i0;
    auto quantised = [&](int i) { return glm::round(f(i / 255.0f) * 255.0f) / 255.0f; };
    return glm::mix(quantised(i0), quantised(i1), t);
}

glm::vec3 grey_kd() {
    const Rgb c = palette_colour(make_test_palette(), kGrey);
    return glm::vec3(c.r, c.g, c.b) / 255.0f;
}

Rgb to_rgb(glm::vec3 c) {
    c = glm::clamp(c, 0.0f, 1.0f) * 255.0f;
    return {static_cast<int>(std::lround(c.r)), static_cast<int>(std::lround(c.g)),
            static_cast<int>(std::lround(c.b))};
}

glm::vec3 cube_at(const glm::vec3 (&cube)[6], glm::vec3 n) {
    const glm::vec3 n2 = n * n;
    return n2.x * (n.x >= 0 ? cube[0] : cube[1]) + n2.y * (n.y >= 0 ? cube[2] : cube[3]) +
           n2.z * (n.z >= 0 ? cube[4] : cube[5]);
}

// Only the terms a test asks for.
IllustrativeSettings terms(bool specular, bool rim, bool dedicated_rim) {
    IllustrativeSettings s;
    s.specular = specular;
    s.rim = rim;
    s.dedicated_rim = dedicated_rim;
    s.skin_masks = false;  // k_s = k_r = 1
    return s;
}

class IllustrativeShadingTest : public GlSuiteTest<IllustrativeShadingTest> {
  protected:
    void SetUp() override {
        GlSuiteTest::SetUp();
        if (HasFatalFailure()) return;
        std::string error;
        ASSERT_TRUE(drawer_.init(&tracker_, error)) << error;
        ramp_a_ =
            gl::create_rgba8_texture(&tracker_, 256, 1, ramp_texels(ramp_a), gl::kLinearClamp);
        ramp_b_ =
            gl::create_rgba8_texture(&tracker_, 256, 1, ramp_texels(ramp_b), gl::kLinearClamp);
        entity_ = make_entity(1);
        entity_.light = &lit_.light;
        set_cube(glm::vec3(0.0f));
    }

    void TearDown() override {
        model_.reset();
        gpu_.reset();
        ramp_a_.reset();
        ramp_b_.reset();
        masks_.reset();
        drawer_.reset();
        EXPECT_EQ(tracker_.total_live(), 0);
    }

    void upload_sphere(uint8_t skin_index) {
        make_sphere(builder_, {4, 4});
        builder_.skin.assign(64, skin_index);
        std::string error;
        gpu_ = classic::AliasModelGpu::create(&tracker_, *builder_.build(), palette_.data(), error);
        ASSERT_TRUE(gpu_) << error;
        model_ = illustrative::IllustrativeModel::create(
            &tracker_, gpu_->model(), illustrative::mdl_vertex_normals(gpu_->model()), error);
        ASSERT_TRUE(model_) << error;
    }

    void set_cube(glm::vec3 colour) {
        for (auto& face : cube_) face = colour;
        store_cube();
    }
    void store_cube() {
        for (int f = 0; f < 6; ++f) std::copy_n(&cube_[f].x, 3, lit_.light.ambient_cube[f]);
    }

    // One white light far away in direction `toward` (world), or none.
    void light_from(glm::vec3 toward, glm::vec3 colour = glm::vec3(1.0f)) {
        lit_.light.num_lights = 1;
        nqr_light_source& light = lit_.sources[0];
        light.size = sizeof(nqr_light_source);
        const glm::vec3 position = glm::normalize(toward) * 1.0e5f;
        std::copy_n(&position.x, 3, light.position);
        std::copy_n(&colour.x, 3, light.color);
    }
    void no_lights() { lit_.light.num_lights = 0; }

    std::vector<Rgb> draw(IllustrativeSettings settings, ShowTerm show, GLuint warp,
                          GLuint masks = 0) {
        settings.show = show;
        gl_->clear(kBackground);
        npr::FrameView view;
        EXPECT_TRUE(npr::read_frame_view(frame_.build(make_camera(kEye, {}), 0), view));
        const classic::SkinImageGpu* image = gpu_->skin_image(0, 0);
        classic::begin_classic_pass();
        AliasShadingTextures textures;
        textures.skin = image->base.id();
        textures.masks = masks;
        EXPECT_TRUE(drawer_.begin(view, settings, warp));
        drawer_.draw(view, entity_, *gpu_, *model_, textures, settings.material);
        drawer_.end();
        EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
        return gl_->pixels();
    }

    // Pixel (x, y) and its sphere normal, for every pixel well inside the outline (facets show
    // near it) on a grid of `step`.
    template <class F>
    void for_inner_pixels(int step, float min_n_dot_v, F check) const {
        for (int y = 0; y < kSize; y += step) {
            for (int x = 0; x < kSize; x += step) {
                const std::optional<glm::vec3> n = sphere_normal_at_pixel(x, y, kEye);
                if (!n) continue;
                const glm::vec3 v = glm::normalize(kEye - *n * kSphereRadius);
                if (glm::dot(*n, v) < min_n_dot_v) continue;
                check(x, y, *n, v);
            }
        }
    }

    std::array<uint8_t, 768> palette_ = make_test_palette();
    gl::ObjectTracker tracker_;
    AliasShadingDrawer drawer_;
    AliasBuilder builder_;
    std::unique_ptr<classic::AliasModelGpu> gpu_;
    std::unique_ptr<illustrative::IllustrativeModel> model_;
    gl::Texture ramp_a_, ramp_b_, masks_;
    glm::vec3 cube_[6];
    nqr_entity entity_{};
    TestLight lit_;  // entity_.light points here
    TestFrame frame_;
};

constexpr int kTolerance = 4;

#define EXPECT_COLOUR(actual, expected, tolerance)                                       \
    EXPECT_TRUE(near((actual), (expected), (tolerance))) << "drawn " << (actual) << ", " \
                                                         << "expected " << (expected)

// ------------------------------------------------------------------ view-independent terms

TEST_F(IllustrativeShadingTest, DiffuseIsTheWarpRampReadAtHalfLambertTimesTwo) {
    upload_sphere(kGrey);
    const IllustrativeSettings s = terms(false, false, false);
    const glm::vec3 l = glm::normalize(glm::vec3(-1.0f, 0.5f, 1.0f));
    light_from(l);
    const std::vector<Rgb> image = draw(s, ShowTerm::final, ramp_a_.id());
    const glm::vec3 kd = grey_kd();
    int checked = 0, wrong = 0;
    for_inner_pixels(3, 0.5f, [&](int x, int y, glm::vec3 n, glm::vec3) {
        const float half_lambert = 0.5f * glm::dot(n, l) + 0.5f;
        const Rgb expected = to_rgb(kd * 2.0f * sample_ramp(ramp_a, half_lambert));
        ++checked;
        wrong += !near(image[y * kSize + x], expected, 8);
    });
    EXPECT_GT(checked, 150);
    EXPECT_LE(wrong, checked / 50) << wrong << " of " << checked;
}

TEST_F(IllustrativeShadingTest, HalfLambertParametersShapeTheRampCoordinate) {
    upload_sphere(kGrey);
    IllustrativeSettings s = terms(false, false, false);
    s.half_lambert_alpha = 1.0f;  // plain Lambert, squared
    s.half_lambert_beta = 0.0f;
    s.half_lambert_gamma = 2.0f;
    const float n_dot_l = 0.6f;
    light_from({-n_dot_l, 0.0f, std::sqrt(1.0f - n_dot_l * n_dot_l)});
    const std::vector<Rgb> image = draw(s, ShowTerm::warped_diffuse, ramp_a_.id());
    const glm::vec2 pole = project(make_camera(kEye, {}), {-kSphereRadius, 0.0f, 0.0f});
    const Rgb drawn = image[int(pole.y) * kSize + int(pole.x)];
    EXPECT_COLOUR(drawn, to_rgb(2.0f * sample_ramp(ramp_a, n_dot_l * n_dot_l)), kTolerance);
}

TEST_F(IllustrativeShadingTest, AmbientCubeWeighsEachFaceBySquaredNormal) {
    upload_sphere(kGrey);
    no_lights();
    cube_[0] = {0.9f, 0.1f, 0.1f};  // +X (the far side: never seen)
    cube_[1] = {0.2f, 0.6f, 0.2f};  // -X, toward the camera
    cube_[2] = {0.1f, 0.1f, 0.9f};  // +Y
    cube_[3] = {0.5f, 0.5f, 0.0f};  // -Y
    cube_[4] = {0.8f, 0.8f, 0.8f};  // +Z
    cube_[5] = {0.0f, 0.1f, 0.3f};  // -Z
    store_cube();
    const std::vector<Rgb> image = draw(terms(false, false, false), ShowTerm::final, ramp_a_.id());
    const glm::vec3 kd = grey_kd();
    int checked = 0, wrong = 0;
    for_inner_pixels(3, 0.5f, [&](int x, int y, glm::vec3 n, glm::vec3) {
        ++checked;
        wrong += !near(image[y * kSize + x], to_rgb(kd * cube_at(cube_, n)), 8);
    });
    EXPECT_GT(checked, 150);
    EXPECT_LE(wrong, checked / 50) << wrong << " of " << checked;
}

// Lights past ill_max_lights are not dropped: each joins the ambient cube as
// c max(0, axis . l) on every face, so a(n) grows by about c max(0, n . l).
TEST_F(IllustrativeShadingTest, LightsPastThePerPixelBudgetJoinTheAmbientCube) {
    upload_sphere(kGrey);
    set_cube(glm::vec3(0.1f));
    const glm::vec3 kept(-1.0f, 0.0f, 0.0f), folded = glm::normalize(glm::vec3(-1.0f, 1.0f, 1.0f));
    const glm::vec3 colours[2] = {glm::vec3(0.5f), glm::vec3(0.4f, 0.3f, 0.2f)};
    lit_.light.num_lights = 2;
    for (int i = 0; i < 2; ++i) {
        nqr_light_source& light = lit_.sources[i];
        light.size = sizeof(nqr_light_source);
        const glm::vec3 position = glm::normalize(i == 0 ? kept : folded) * 1.0e5f;
        std::copy_n(&position.x, 3, light.position);
        std::copy_n(&colours[i].x, 3, light.color);
    }
    IllustrativeSettings s = terms(false, false, false);
    s.max_lights = 1;
    glm::vec3 expected_cube[6];
    for (int axis = 0; axis < 3; ++axis) {
        expected_cube[2 * axis] = cube_[2 * axis] + colours[1] * std::max(folded[axis], 0.0f);
        expected_cube[2 * axis + 1] =
            cube_[2 * axis + 1] + colours[1] * std::max(-folded[axis], 0.0f);
    }
    const std::vector<Rgb> ambient = draw(s, ShowTerm::ambient, ramp_a_.id());
    int checked = 0, wrong = 0;
    for_inner_pixels(3, 0.5f, [&](int x, int y, glm::vec3 n, glm::vec3) {
        ++checked;
        wrong += !near(ambient[y * kSize + x], to_rgb(cube_at(expected_cube, n)), 8);
    });
    EXPECT_GT(checked, 150);
    EXPECT_LE(wrong, checked / 50) << wrong << " of " << checked;
    // The kept light is still per pixel, warped: the diffuse light term is its ramp alone.
    const glm::vec2 pole = project(make_camera(kEye, {}), {-kSphereRadius, 0.0f, 0.0f});
    const Rgb warped =
        draw(s, ShowTerm::warped_diffuse, ramp_a_.id())[int(pole.y) * kSize + int(pole.x)];
    EXPECT_COLOUR(warped, to_rgb(colours[0] * 2.0f * sample_ramp(ramp_a, 1.0f)), kTolerance);
    // With the budget at 2 both are per pixel and the cube is the map's alone.
    s.max_lights = 2;
    EXPECT_COLOUR(draw(s, ShowTerm::ambient, ramp_a_.id())[int(pole.y) * kSize + int(pole.x)],
                  to_rgb(glm::vec3(0.1f)), kTolerance);
}

// The final colour is drawn by programs compiled for it (a fixed light count, no ill_show);
// it must be what the general program's terms add up to.
TEST_F(IllustrativeShadingTest, TheFinalColourIsTheSumOfTheTermsShownAlone) {
    upload_sphere(kGrey);
    set_cube(glm::vec3(0.15f, 0.2f, 0.25f));
    for (int lights = 0; lights <= 4; ++lights) {
        lit_.light.num_lights = lights;
        for (int i = 0; i < lights; ++i) {
            nqr_light_source& light = lit_.sources[i];
            light.size = sizeof(nqr_light_source);
            const glm::vec3 position = glm::normalize(glm::vec3(-1.0f, i - 1.5f, 0.7f)) * 1.0e5f;
            std::copy_n(&position.x, 3, light.position);
            const glm::vec3 colour(0.3f, 0.25f, 0.2f);
            std::copy_n(&colour.x, 3, light.color);
        }
        IllustrativeSettings s = terms(true, true, true);
        s.max_lights = 4;
        for (float gamma : {1.0f, 2.0f}) {
            s.half_lambert_gamma = gamma;
            const std::vector<Rgb> final_colour = draw(s, ShowTerm::final, ramp_a_.id());
            const std::vector<Rgb> diffuse = draw(s, ShowTerm::diffuse_total, ramp_a_.id());
            const std::vector<Rgb> view = draw(s, ShowTerm::view_dependent, ramp_a_.id());
            int checked = 0, wrong = 0;
            for_inner_pixels(2, 0.2f, [&](int x, int y, glm::vec3, glm::vec3) {
                const size_t i = size_t(y) * kSize + size_t(x);
                const Rgb sum{std::min(255, diffuse[i].r + view[i].r),
                              std::min(255, diffuse[i].g + view[i].g),
                              std::min(255, diffuse[i].b + view[i].b)};
                ++checked;
                wrong += !near(final_colour[i], sum, 2);
            });
            EXPECT_GT(checked, 300);
            EXPECT_EQ(wrong, 0) << lights << " lights, gamma " << gamma;
        }
    }
}

TEST_F(IllustrativeShadingTest, SwappingTheRampChangesExactlyTheDiffuseTerm) {
    upload_sphere(kGrey);
    set_cube(glm::vec3(0.3f, 0.35f, 0.4f));
    light_from({-1.0f, 1.0f, 0.5f});
    const IllustrativeSettings s = terms(true, true, true);
    EXPECT_NE(draw(s, ShowTerm::warped_diffuse, ramp_a_.id()),
              draw(s, ShowTerm::warped_diffuse, ramp_b_.id()));
    EXPECT_NE(draw(s, ShowTerm::final, ramp_a_.id()), draw(s, ShowTerm::final, ramp_b_.id()));
    for (ShowTerm unchanged : {ShowTerm::albedo, ShowTerm::ambient, ShowTerm::specular,
                               ShowTerm::rim, ShowTerm::view_dependent}) {
        EXPECT_EQ(draw(s, unchanged, ramp_a_.id()), draw(s, unchanged, ramp_b_.id()))
            << "term " << static_cast<int>(unchanged);
    }
}

TEST_F(IllustrativeShadingTest, TheTf2RampShadesCoolNotBlackWithARedTerminatorAndGreyLight) {
    upload_sphere(kGrey);
    gl::Texture tf2 = illustrative::create_warp_texture(&tracker_, illustrative::tf2_warp_ramp());
    const IllustrativeSettings s = terms(false, false, false);
    const glm::vec2 pole = project(make_camera(kEye, {}), {-kSphereRadius, 0.0f, 0.0f});
    auto pole_lit_at = [&](float n_dot_l) {  // the pole's normal is -X
        light_from({-n_dot_l, 0.0f, std::sqrt(std::max(0.0f, 1.0f - n_dot_l * n_dot_l))});
        return draw(s, ShowTerm::final, tf2.id())[int(pole.y) * kSize + int(pole.x)];
    };
    const Rgb dark = pole_lit_at(-1.0f), terminator = pole_lit_at(0.0f), lit = pole_lit_at(1.0f);
    // Facing away: cool (blue above red), and not black.
    EXPECT_GT(dark.b, dark.r + 10) << dark;
    EXPECT_GT(brightness(dark), 20) << dark;
    // The terminator band: red above green and blue.
    EXPECT_GT(terminator.r, terminator.g + 5) << terminator;
    EXPECT_GT(terminator.r, terminator.b + 5) << terminator;
    // Lit: grey, brighter than the grey skin itself (the ramp ends above mid-grey, read x2).
    EXPECT_LE(std::abs(lit.r - lit.g) + std::abs(lit.g - lit.b), 12) << lit;
    EXPECT_GT(brightness(lit), brightness(palette_colour(palette_, kGrey))) << lit;
    tf2.reset();
}

// ------------------------------------------------------------------ view-dependent terms

TEST_F(IllustrativeShadingTest, SpecularFacingTheLightIsTheFirstFresnelRangeTimesBoost) {
    upload_sphere(kGrey);
    light_from({-1.0f, 0.0f, 0.0f});  // behind the camera: n.l = v.r = n.v = 1 at the pole
    IllustrativeSettings s = terms(true, false, false);
    s.material.fresnel_ranges[0] = 0.5f;
    s.material.phong_boost = 0.6f;
    const std::vector<Rgb> image = draw(s, ShowTerm::specular, ramp_a_.id());
    const glm::vec2 pole = project(make_camera(kEye, {}), {-kSphereRadius, 0.0f, 0.0f});
    EXPECT_COLOUR(image[int(pole.y) * kSize + int(pole.x)], to_rgb(glm::vec3(0.5f * 0.6f)),
                  kTolerance);
}

TEST_F(IllustrativeShadingTest, PhongFollowsTheReflectedLightWithFresnelRanges) {
    upload_sphere(kGrey);
    const glm::vec3 l = glm::normalize(glm::vec3(-1.0f, -0.6f, 0.4f));
    light_from(l);
    IllustrativeSettings s = terms(true, false, false);
    s.material.phong_exponent = 8.0f;
    s.material.phong_boost = 1.0f;
    const std::vector<Rgb> image = draw(s, ShowTerm::specular, ramp_a_.id());
    const MaterialParams& m = s.material;
    int checked = 0, wrong = 0;
    for_inner_pixels(3, 0.5f, [&](int x, int y, glm::vec3 n, glm::vec3 v) {
        float f = 1.0f - glm::dot(n, v);
        f *= f;
        const float f_s = f > 0.5f ? glm::mix(m.fresnel_ranges[1], m.fresnel_ranges[2], 2 * f - 1)
                                   : glm::mix(m.fresnel_ranges[0], m.fresnel_ranges[1], 2 * f);
        const glm::vec3 r = glm::reflect(-l, n);
        const float spec = f_s * std::pow(std::max(glm::dot(v, r), 0.0f), m.phong_exponent);
        ++checked;
        wrong += !near(image[y * kSize + x], to_rgb(glm::vec3(spec)), 8);
    });
    EXPECT_GT(checked, 150);
    EXPECT_LE(wrong, checked / 50) << wrong << " of " << checked;
}

TEST_F(IllustrativeShadingTest, RimLightBrightensOnlyGrazingPixels) {
    upload_sphere(kGrey);
    light_from({1.0f, 0.0f, 0.2f});  // behind the sphere: back-lit
    const std::vector<Rgb> image = draw(terms(true, true, false), ShowTerm::rim, ramp_a_.id());
    int facing_bright = 0, grazing_max = 0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const std::optional<glm::vec3> n = sphere_normal_at_pixel(x, y, kEye);
            if (!n) continue;
            const glm::vec3 v = glm::normalize(kEye - *n * kSphereRadius);
            const float n_dot_v = glm::dot(*n, v);
            const int value = brightness(image[y * kSize + x]);
            if (n_dot_v > 0.6f) facing_bright += value > 3;
            if (n_dot_v < 0.25f) grazing_max = std::max(grazing_max, value);
        }
    }
    EXPECT_EQ(facing_bright, 0);
    EXPECT_GT(grazing_max, 60);
}

TEST_F(IllustrativeShadingTest, DedicatedRimLightsOnlyUpwardFacingPixelsFromTheCubeBehind) {
    upload_sphere(kGrey);
    no_lights();
    set_cube(glm::vec3(0.0f));
    cube_[0] = glm::vec3(1.0f);  // light arriving from +X: behind the sphere, along the view ray
    store_cube();
    const IllustrativeSettings s = terms(false, false, true);
    const std::vector<Rgb> image = draw(s, ShowTerm::rim, ramp_a_.id());
    int checked = 0, wrong = 0, lower_lit = 0, upper_max = 0;
    for_inner_pixels(2, 0.05f, [&](int x, int y, glm::vec3 n, glm::vec3 v) {
        const Rgb drawn = image[y * kSize + x];
        if (n.z < -0.05f) lower_lit += brightness(drawn) > 2;
        if (n.z > 0.3f) upper_max = std::max(upper_max, brightness(drawn));
        // Near the outline f_r = (1 - n.v)^4 magnifies the facets' error: the formula is
        // checked where the sphere's normal is what the mesh shows.
        if (glm::dot(n, v) < 0.25f) return;
        const float f_r = std::pow(1.0f - glm::dot(n, v), 4.0f);
        const glm::vec3 expected =
            std::max(n.z, 0.0f) * f_r * s.material.rim_boost * cube_at(cube_, -v);
        ++checked;
        wrong += !near(drawn, to_rgb(expected), 8);
    });
    EXPECT_GT(checked, 500);
    EXPECT_EQ(lower_lit, 0);
    EXPECT_GT(upper_max, 60);
    EXPECT_LE(wrong, checked / 50) << wrong << " of " << checked;
    // In the dark (an empty cube) nothing glows.
    set_cube(glm::vec3(0.0f));
    const std::vector<Rgb> dark = draw(s, ShowTerm::rim, ramp_a_.id());
    EXPECT_TRUE(std::all_of(dark.begin(), dark.end(), [](Rgb c) { return brightness(c) == 0; }));
}

// ------------------------------------------------------------------ read hierarchy

TEST_F(IllustrativeShadingTest, TeamColourTexelsAreSaturatedAndOthersAreNot) {
    upload_sphere(colour::kRed);
    std::vector<uint8_t> team(4 * 4 * 4, 255);  // every texel marked shirt/pants
    masks_ = gl::create_rgba8_texture(&tracker_, 4, 4, team, gl::kNearestClamp);
    IllustrativeSettings s = terms(false, false, false);
    s.skin_masks = true;
    s.team_saturation = 1.5f;
    entity_.has_translation = 1;
    const Rgb red = palette_colour(palette_, colour::kRed);
    const glm::vec3 kd = glm::vec3(red.r, red.g, red.b) / 255.0f;
    const float luma = glm::dot(kd, glm::vec3(0.299f, 0.587f, 0.114f));
    const glm::vec3 saturated = glm::clamp(glm::mix(glm::vec3(luma), kd, 1.5f), 0.0f, 1.0f);
    const glm::vec2 pole = project(make_camera(kEye, {}), {-kSphereRadius, 0.0f, 0.0f});
    const size_t at = size_t(pole.y) * kSize + size_t(pole.x);
    EXPECT_COLOUR(draw(s, ShowTerm::albedo, ramp_a_.id(), masks_.id())[at], to_rgb(saturated),
                  kTolerance);
    EXPECT_COLOUR(draw(s, ShowTerm::albedo, ramp_a_.id())[at], red, kTolerance);  // no team mask
    entity_.has_translation = 0;  // not a player: no team read
    EXPECT_COLOUR(draw(s, ShowTerm::albedo, ramp_a_.id(), masks_.id())[at], red, kTolerance);
}

// ------------------------------------------------------------------ normals

TEST_F(IllustrativeShadingTest, NormalsThatDoNotFitTheModelAreRefusedWithAReason) {
    upload_sphere(kGrey);
    illustrative::CornerNormals normals = illustrative::mdl_vertex_normals(gpu_->model());
    normals.corner_slots.back() = normals.num_slots;  // out of range
    std::string error;
    EXPECT_EQ(illustrative::IllustrativeModel::create(&tracker_, gpu_->model(), normals, error),
              nullptr);
    EXPECT_NE(error.find("out of range"), std::string::npos) << error;
    normals = illustrative::mdl_vertex_normals(gpu_->model());
    normals.normals.pop_back();
    error.clear();
    EXPECT_EQ(illustrative::IllustrativeModel::create(&tracker_, gpu_->model(), normals, error),
              nullptr);
    EXPECT_NE(error.find("poses"), std::string::npos) << error;
}

TEST_F(IllustrativeShadingTest, TheNormalsDrawnAreTheSlotNormalsNotThePoseNormals) {
    // Every slot normal replaced by +Z: the ambient cube then shows the +Z face everywhere.
    upload_sphere(kGrey);
    illustrative::CornerNormals normals = illustrative::mdl_vertex_normals(gpu_->model());
    for (glm::vec3& n : normals.normals) n = glm::vec3(0, 0, 1);
    std::string error;
    model_ = illustrative::IllustrativeModel::create(&tracker_, gpu_->model(), normals, error);
    ASSERT_TRUE(model_) << error;
    no_lights();
    set_cube(glm::vec3(0.0f));
    cube_[4] = glm::vec3(0.8f);
    store_cube();
    const std::vector<Rgb> image =
        draw(terms(false, false, false), ShowTerm::ambient, ramp_a_.id());
    int checked = 0, wrong = 0;
    for_inner_pixels(4, 0.3f, [&](int x, int y, glm::vec3, glm::vec3) {
        ++checked;
        wrong += !near(image[y * kSize + x], to_rgb(glm::vec3(0.8f)), 3);
    });
    EXPECT_GT(checked, 50);
    EXPECT_EQ(wrong, 0);
}

}  // namespace
}  // namespace nq::npr::test

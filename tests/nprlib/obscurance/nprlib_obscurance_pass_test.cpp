// The volumetric obscurance pass (nprlib/obscurance/obscurance_pass) on real pixels (Mesa
// llvmpipe), over G-buffers ray-cast here from planes, against volumes computed here: a flat
// floor stays open with the normal clamp; a floor meeting a wall is darkened by the part of the
// hemisphere the wall cuts off, 1 - (R - h)^2 (2R + h) / (4 R^3) at distance h from it; a
// foreground edge leaves no halo on the background behind it with a thickness (and does
// without); the blur keeps the wall's and the floor's values apart; shifting the samples per
// pixel brings the estimate closer to the converged one; sky is never darkened; the colour is
// multiplied by the result, or shows it alone.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "support/nprlib_test_support.h"
#include "obscurance/obscurance_pass.h"

namespace nq::npr::test {
namespace {

using obscurance::ObscuranceMode;
using obscurance::ObscurancePass;
using obscurance::ObscuranceSettings;
using obscurance::StagePath;
using obscurance::StageTrial;
using obscurance::TimedStage;

constexpr float kNear = 4.0f, kFar = 4096.0f;

// What a pixel's ray hits: its distance along the view axis and its view-space normal.
struct Hit {
    float distance;
    glm::vec3 normal;
};
// A plane n . x = d in view space (the camera at the origin looking down -z).
struct Plane {
    glm::vec3 normal;
    float d;
};

class ObscurancePassTest : public GlSuiteTest<ObscurancePassTest> {
  protected:
    void SetUp() override {
        GlSuiteTest::SetUp();
        if (HasFatalFailure()) return;
        projection_ = glm::perspective(glm::radians(90.0f), 1.0f, kNear, kFar);
        colour_ = make_texture(GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE);
        normal_ = make_texture(GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE);
        depth_ = make_texture(GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT, GL_FLOAT);
        glGenFramebuffers(1, &framebuffer_);
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour_, 0);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, normal_, 0);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth_, 0);
        ASSERT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
    }

    void TearDown() override {
        pass_.reset();
        EXPECT_EQ(tracker_.total_live(), 0);
        glDeleteFramebuffers(1, &framebuffer_);
        GLuint textures[] = {colour_, normal_, depth_};
        glDeleteTextures(3, textures);
    }

    static GLuint make_texture(GLenum internal_format, GLenum format, GLenum type) {
        GLuint texture = 0;
        glGenTextures(1, &texture);
        glBindTexture(GL_TEXTURE_2D, texture);
        glTexImage2D(GL_TEXTURE_2D, 0, internal_format, kSize, kSize, 0, format, type, nullptr);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        return texture;
    }

    // The view ray through pixel (x, y)'s centre, scaled so that its z is -1.
    glm::vec3 ray(int x, int y) const {
        const float ndc_x = (x + 0.5f) / (kSize / 2.0f) - 1.0f;
        const float ndc_y = (y + 0.5f) / (kSize / 2.0f) - 1.0f;
        return {ndc_x / projection_[0][0], ndc_y / projection_[1][1], -1.0f};
    }

    // Ray-casts the nearest plane per pixel into the depth and normal textures (no hit: sky),
    // and fills the colour with white.
    void build_scene(const std::vector<Plane>& planes) {
        hits_.assign(size_t(kSize) * kSize, std::nullopt);
        std::vector<float> depth(size_t(kSize) * kSize, 1.0f);
        std::vector<uint8_t> normals(size_t(kSize) * kSize * 4, 0);
        for (int y = 0; y < kSize; ++y) {
            for (int x = 0; x < kSize; ++x) {
                const glm::vec3 r = ray(x, y);
                std::optional<Hit> best;
                for (const Plane& plane : planes) {
                    const float along = glm::dot(plane.normal, r);
                    if (along >= -1e-6f) continue;    // parallel or seen from behind
                    const float t = plane.d / along;  // the hit is r * t, distance t
                    if (t > kNear && (!best || t < best->distance)) best = Hit{t, plane.normal};
                }
                const size_t i = size_t(y) * kSize + size_t(x);
                hits_[i] = best;
                if (!best) continue;
                const glm::vec4 clip = projection_ * glm::vec4(r * best->distance, 1.0f);
                depth[i] = clip.z / clip.w * 0.5f + 0.5f;
                const glm::vec3 encoded = best->normal * 0.5f + 0.5f;
                for (int k = 0; k < 3; ++k)
                    normals[i * 4 + k] = uint8_t(std::lround(encoded[k] * 255));
                normals[i * 4 + 3] = 255;
            }
        }
        glBindTexture(GL_TEXTURE_2D, depth_);
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, kSize, kSize, GL_DEPTH_COMPONENT, GL_FLOAT,
                        depth.data());
        glBindTexture(GL_TEXTURE_2D, normal_);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, kSize, kSize, GL_RGBA, GL_UNSIGNED_BYTE,
                        normals.data());
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
        const GLfloat white[] = {1, 1, 1, 1};
        glClearBufferfv(GL_COLOR, 0, white);
    }

    // The left half of the view is a wall facing the camera at distance 100, the right half
    // one at 400.
    void build_foreground_edge() {
        hits_.assign(size_t(kSize) * kSize, std::nullopt);
        std::vector<float> depth(size_t(kSize) * kSize);
        std::vector<uint8_t> normals(size_t(kSize) * kSize * 4, 255);
        for (int y = 0; y < kSize; ++y) {
            for (int x = 0; x < kSize; ++x) {
                const size_t i = size_t(y) * kSize + size_t(x);
                const float distance = x < kSize / 2 ? 100.0f : 400.0f;
                hits_[i] = Hit{distance, {0.0f, 0.0f, 1.0f}};
                const glm::vec4 clip = projection_ * glm::vec4(ray(x, y) * distance, 1.0f);
                depth[i] = clip.z / clip.w * 0.5f + 0.5f;
                normals[i * 4 + 0] = normals[i * 4 + 1] = 128;
            }
        }
        glBindTexture(GL_TEXTURE_2D, depth_);
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, kSize, kSize, GL_DEPTH_COMPONENT, GL_FLOAT,
                        depth.data());
        glBindTexture(GL_TEXTURE_2D, normal_);
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, kSize, kSize, GL_RGBA, GL_UNSIGNED_BYTE,
                        normals.data());
    }

    // The lowest value of `drawn` in columns [x0, x1), rows 8 .. kSize - 8 (off the borders).
    static float lowest_in_columns(const std::vector<float>& drawn, int x0, int x1) {
        float lowest = 1.0f;
        for (int y = 8; y < kSize - 8; ++y) {
            for (int x = x0; x < x1; ++x)
                lowest = std::min(lowest, drawn[size_t(y) * kSize + size_t(x)]);
        }
        return lowest;
    }

    // Runs the pass; the scene colour (white before) per pixel, 0..1 from its red channel.
    // `side`: the scene's width and height, the lower-left part of the textures.
    std::vector<float> run(const ObscuranceSettings& settings, int side = kSize) {
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
        const GLfloat white[] = {1, 1, 1, 1};
        glClearBufferfv(GL_COLOR, 0, white);
        obscurance::SceneTextures scene;
        scene.framebuffer = framebuffer_;
        scene.depth_texture = depth_;
        scene.normal_texture = normal_;
        scene.width = scene.height = side;
        std::copy_n(glm::value_ptr(projection_), 16, scene.projection);
        std::string error;
        EXPECT_TRUE(pass_.apply(scene, settings, error)) << error;
        EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
        std::vector<uint8_t> rgba(size_t(kSize) * kSize * 4);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
        glReadBuffer(GL_COLOR_ATTACHMENT0);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, kSize, kSize, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
        std::vector<float> out(size_t(kSize) * kSize);
        for (size_t i = 0; i < out.size(); ++i) out[i] = rgba[i * 4] / 255.0f;
        return out;
    }

    // Mean |drawn - expected| over pixels with a hit where `expected` gives a value.
    float mean_error(
        const std::vector<float>& drawn,
        const std::function<std::optional<float>(glm::vec3 point, const Hit&)>& expected,
        int& counted) const {
        double sum = 0.0;
        counted = 0;
        for (int y = 0; y < kSize; ++y) {
            for (int x = 0; x < kSize; ++x) {
                const size_t i = size_t(y) * kSize + size_t(x);
                if (!hits_[i]) continue;
                const std::optional<float> e = expected(ray(x, y) * hits_[i]->distance, *hits_[i]);
                if (!e) continue;
                sum += std::abs(drawn[i] - *e);
                ++counted;
            }
        }
        return counted ? float(sum / counted) : 1.0f;
    }

    static ObscuranceSettings settings_for(ObscuranceMode mode) {
        ObscuranceSettings s;
        s.enabled = true;
        s.mode = mode;
        s.blur = false;
        return s;
    }

    // For build_foreground_edge: a sphere large enough (48) that the near wall reaches into the
    // far wall's spheres beside the silhouette, with `thickness`.
    static ObscuranceSettings edge_settings(ObscuranceMode mode, float thickness) {
        ObscuranceSettings s = settings_for(mode);
        s.radius = 48.0f;
        s.thickness = thickness;
        return s;
    }

    gl::ObjectTracker tracker_;
    ObscurancePass pass_{&tracker_};
    glm::mat4 projection_;
    GLuint colour_ = 0, normal_ = 0, depth_ = 0, framebuffer_ = 0;
    std::vector<std::optional<Hit>> hits_;
};

constexpr ObscuranceMode kModes[] = {ObscuranceMode::lines5,   ObscuranceMode::lines9,
                                     ObscuranceMode::points12, ObscuranceMode::points33,
                                     ObscuranceMode::area1,    ObscuranceMode::reference};

// The floor y = -40 and the wall z = -160 (view space), meeting in a crease across the view.
const Plane kFloor{{0.0f, 1.0f, 0.0f}, -40.0f};
const Plane kWall{{0.0f, 0.0f, 1.0f}, -160.0f};

// How far a point of the floor is from the wall, or a point of the wall from the floor.
float distance_to_crease(glm::vec3 p, const Hit& hit) {
    return hit.normal.y > 0.5f ? p.z - kWall.d * kWall.normal.z : p.y - kFloor.d;
}

// The open fraction of the hemisphere above a surface at distance h < R from a perpendicular
// wall: the wall cuts a cap of height R - h off the sphere, half of it above the surface.
float open_near_wall(float h, float radius) {
    if (h >= radius) return 1.0f;
    const float cut =
        (radius - h) * (radius - h) * (2.0f * radius + h) / (4.0f * radius * radius * radius);
    return 1.0f - cut;
}

TEST_F(ObscurancePassTest, AFlatFloorStaysOpenWithTheNormalClamp) {
    build_scene({kFloor});
    for (ObscuranceMode mode : kModes) {
        const std::vector<float> drawn = run(settings_for(mode));
        int counted = 0;
        const float error = mean_error(
            drawn, [](glm::vec3, const Hit&) { return 1.0f; }, counted);
        EXPECT_GT(counted, kSize * kSize / 3);
        // Points sit on depth texels spanning long stretches of a floor seen at a grazing angle.
        const bool points = mode == ObscuranceMode::points12 || mode == ObscuranceMode::points33;
        EXPECT_LT(error, points ? 0.04f : 0.025f) << obscurance::obscurance_mode_name(mode);
        if (mode == ObscuranceMode::reference) {
            EXPECT_LT(error, 0.01f);
        }
    }
}

TEST_F(ObscurancePassTest, TheCreaseIsDarkenedByTheVolumeTheWallCutsOff) {
    build_scene({kFloor, kWall});
    ObscuranceSettings s = settings_for(ObscuranceMode::lines9);
    s.radius = 24.0f;
    s.thickness = 0.0f;
    const auto expected = [&](glm::vec3 p, const Hit& hit) -> std::optional<float> {
        // Floor: distance to the wall plane z = -160; wall: height above the floor y = -40.
        const float distance = distance_to_crease(p, hit);
        return open_near_wall(distance, s.radius);
    };
    for (ObscuranceMode mode : kModes) {
        s.mode = mode;
        const std::vector<float> drawn = run(s);
        int counted = 0;
        EXPECT_LT(mean_error(drawn, expected, counted), 0.06f)
            << obscurance::obscurance_mode_name(mode);
        // Near the crease only: the darkening is really there, not a constant near 1.
        const auto near_crease = [&](glm::vec3 p, const Hit& hit) -> std::optional<float> {
            const float distance = distance_to_crease(p, hit);
            if (distance > 0.5f * s.radius) return std::nullopt;
            return open_near_wall(distance, s.radius);
        };
        // Points are the coarser estimate (the paper's point: 12 points err more than 5 lines);
        // the converged lines are the depth buffer's own answer, off the true volume only by
        // its resolution (the sphere spans ~20 of the view's 128 texels here).
        const float tolerance = mode == ObscuranceMode::points12    ? 0.18f
                                : mode == ObscuranceMode::reference ? 0.08f
                                                                    : 0.11f;
        EXPECT_LT(mean_error(drawn, near_crease, counted), tolerance)
            << obscurance::obscurance_mode_name(mode);
        EXPECT_GT(counted, 100);
        double mean = 0.0;
        int n = 0;
        for (size_t i = 0; i < drawn.size(); ++i) {
            if (!hits_[i]) continue;
            const glm::vec3 p = ray(int(i % kSize), int(i / kSize)) * hits_[i]->distance;
            const float distance = distance_to_crease(p, *hits_[i]);
            if (distance < 0.25f * s.radius) {
                mean += drawn[i];
                ++n;
            }
        }
        ASSERT_GT(n, 0);
        EXPECT_LT(mean / n, 0.8) << obscurance::obscurance_mode_name(mode);  // the truth: ~0.57
    }
}

// A near plane covering the left half in front of a far wall: the wall's pixels beside the
// silhouette must not be darkened by an occluder far in front of their sphere.
TEST_F(ObscurancePassTest, AForegroundEdgeLeavesNoHaloBehindItWithAThickness) {
    build_foreground_edge();
    for (ObscuranceMode mode : kModes) {
        ObscuranceSettings s = edge_settings(mode, 32.0f);
        s.blur = true;
        const std::vector<float> with_thickness = run(s);
        s.thickness = 0.0f;
        s.blur = false;
        const std::vector<float> infinitely_thick = run(s);
        const float lowest_with = lowest_in_columns(with_thickness, kSize / 2, kSize / 2 + 6);
        const float lowest_without = lowest_in_columns(infinitely_thick, kSize / 2, kSize / 2 + 6);
        EXPECT_GE(lowest_with, 0.97f) << obscurance::obscurance_mode_name(mode);
        EXPECT_LT(lowest_without, 0.8f) << obscurance::obscurance_mode_name(mode);
    }
}

// At half resolution the composite upsamples by depth: the foreground beside the silhouette
// takes nothing of the darkened background behind it (no thickness: the background is darkened
// along the edge), as at full resolution.
TEST_F(ObscurancePassTest, HalfResolutionUpsamplesWithoutBleedingAcrossTheEdge) {
    build_foreground_edge();
    for (ObscuranceMode mode : kModes) {
        ObscuranceSettings s = edge_settings(mode, 0.0f);
        s.half_resolution = true;
        for (bool blur : {false, true}) {
            s.blur = blur && mode != ObscuranceMode::reference;
            const std::vector<float> drawn = run(s);
            const float foreground = lowest_in_columns(drawn, kSize / 2 - 6, kSize / 2);
            const float background = lowest_in_columns(drawn, kSize / 2, kSize / 2 + 6);
            EXPECT_GE(foreground, 0.97f) << obscurance::obscurance_mode_name(mode) << blur;
            EXPECT_LT(background, 0.9f) << obscurance::obscurance_mode_name(mode) << blur;
        }
    }
}

TEST_F(ObscurancePassTest, TheBlurKeepsTheWallAndTheFloorApartAndSmoothsThePattern) {
    build_scene({kFloor, kWall});
    ObscuranceSettings s = settings_for(ObscuranceMode::lines5);
    s.thickness = 0.0f;
    const std::vector<float> raw = run(s);
    s.blur = true;
    const std::vector<float> blurred = run(s);
    const auto expected = [&](glm::vec3 p, const Hit& hit) -> std::optional<float> {
        return open_near_wall(distance_to_crease(p, hit), s.radius);
    };
    int counted = 0;
    const float raw_error = mean_error(raw, expected, counted);
    const float blurred_error = mean_error(blurred, expected, counted);
    EXPECT_LT(blurred_error, 0.06f);
    EXPECT_LE(blurred_error, raw_error + 0.005f);
    // The 4x4 rotation pattern is averaged away: neighbours on the floor differ far less.
    const auto roughness = [&](const std::vector<float>& image) {
        double sum = 0.0;
        int n = 0;
        for (int y = 4; y < kSize / 4; ++y) {  // the floor, near the camera
            for (int x = 4; x < kSize - 5; ++x) {
                const size_t i = size_t(y) * kSize + size_t(x);
                sum += std::abs(image[i + 1] - image[i]);
                ++n;
            }
        }
        return sum / n;
    };
    EXPECT_LT(roughness(blurred), 0.25 * roughness(raw));
}

// vo_shift: a ring set turned per pixel samples one radius only, so its blurred estimate is
// biased wherever that radius matters (near the crease); shifted through the sphere's volume
// as well, every sample reaches every radius and the blurred estimate comes closer to the
// depth buffer's converged answer (the reference mode on the same buffer). 33 points already
// lie at many radii: shifting them gains nothing here, but must not cost much either.
TEST_F(ObscurancePassTest, ShiftingTheSamplesBringsTheEstimateCloserToTheReference) {
    build_scene({kFloor, kWall});
    ObscuranceSettings s = settings_for(ObscuranceMode::reference);
    s.thickness = 0.0f;
    const std::vector<float> reference = run(s);
    const auto error_near_crease = [&](const std::vector<float>& drawn) {
        double sum = 0.0;
        int n = 0;
        for (size_t i = 0; i < drawn.size(); ++i) {
            if (!hits_[i]) continue;
            const glm::vec3 p = ray(int(i % kSize), int(i / kSize)) * hits_[i]->distance;
            if (distance_to_crease(p, *hits_[i]) > s.radius) continue;
            sum += std::abs(drawn[i] - reference[i]);
            ++n;
        }
        EXPECT_GT(n, 500);
        return sum / std::max(n, 1);
    };
    s.blur = true;
    for (ObscuranceMode mode : {ObscuranceMode::lines5, ObscuranceMode::lines9,
                                ObscuranceMode::points12, ObscuranceMode::points33}) {
        s.mode = mode;
        s.shift = false;
        const double turned = error_near_crease(run(s));
        s.shift = true;
        const double shifted = error_near_crease(run(s));
        std::printf("%s: mean error near the crease turned %.4f, shifted %.4f\n",
                    std::string(obscurance::obscurance_mode_name(mode)).c_str(), turned, shifted);
        if (mode == ObscuranceMode::points33) {
            EXPECT_LT(shifted, turned + 0.01) << obscurance::obscurance_mode_name(mode);
        } else {
            EXPECT_LT(shifted, 0.7 * turned) << obscurance::obscurance_mode_name(mode);
        }
    }
}

TEST_F(ObscurancePassTest, SkyIsNeverDarkenedAndTheColourIsMultipliedOrShown) {
    build_scene({kFloor});  // the upper half sees nothing: sky
    ObscuranceSettings s = settings_for(ObscuranceMode::lines5);
    std::vector<float> drawn = run(s);
    int sky = 0;
    for (size_t i = 0; i < drawn.size(); ++i) {
        if (hits_[i]) continue;
        ++sky;
        EXPECT_EQ(drawn[i], 1.0f);
    }
    EXPECT_GT(sky, kSize * kSize / 4);
    // Strength 0 leaves the image; show draws the obscurance itself over the colour.
    build_scene({kFloor, kWall});
    s.strength = 0.0f;
    for (float v : run(s)) EXPECT_EQ(v, 1.0f);
    s.strength = 1.0f;
    const std::vector<float> multiplied = run(s);
    s.show = true;
    s.strength = 0.0f;  // show ignores the strength
    const std::vector<float> shown = run(s);
    int darker = 0;
    for (size_t i = 0; i < shown.size(); ++i) {
        EXPECT_NEAR(shown[i], multiplied[i], 1.5f / 255.0f);
        darker += shown[i] < 0.9f;
    }
    EXPECT_GT(darker, 100);
}

// Compositing elsewhere (the engine's window when no plugin post-process follows): the other
// framebuffer's rectangle gets the scene colour times the obscurance, the pixel for pixel
// result of multiplying in place, nothing around it is drawn and the scene keeps its colour.
TEST_F(ObscurancePassTest, CompositingElsewhereWritesTheMultipliedColourThere) {
    build_scene({kFloor, kWall});
    const GLfloat colour[] = {0.8f, 0.5f, 0.25f, 1.0f};
    const auto read_rgb = [](GLuint framebuffer, int x, int y, int w, int h) {
        std::vector<uint8_t> rgb(size_t(w) * size_t(h) * 3);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
        glReadBuffer(GL_COLOR_ATTACHMENT0);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(x, y, w, h, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
        return rgb;
    };
    obscurance::SceneTextures scene;
    scene.framebuffer = framebuffer_;
    scene.colour_texture = colour_;
    scene.depth_texture = depth_;
    scene.normal_texture = normal_;
    scene.width = scene.height = kSize;
    std::copy_n(glm::value_ptr(projection_), 16, scene.projection);
    constexpr int kOtherWidth = kSize + 20, kOtherHeight = kSize + 10, kX = 7, kY = 5;
    GLuint other_texture = 0, other = 0;
    glGenTextures(1, &other_texture);
    glBindTexture(GL_TEXTURE_2D, other_texture);
    glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA8, kOtherWidth, kOtherHeight);
    glGenFramebuffers(1, &other);
    glBindFramebuffer(GL_FRAMEBUFFER, other);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, other_texture, 0);
    obscurance::CompositeTarget elsewhere;
    elsewhere.framebuffer = other;
    const int viewport[4] = {kX, kY, kSize, kSize};
    std::copy_n(viewport, 4, elsewhere.viewport);
    for (bool show : {false, true}) {
        ObscuranceSettings s = settings_for(ObscuranceMode::lines5);
        s.show = show;
        std::string error;
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
        glClearBufferfv(GL_COLOR, 0, colour);
        ASSERT_TRUE(pass_.apply(scene, s, error)) << error;
        const std::vector<uint8_t> in_place = read_rgb(framebuffer_, 0, 0, kSize, kSize);
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
        glClearBufferfv(GL_COLOR, 0, colour);
        glBindFramebuffer(GL_FRAMEBUFFER, other);
        const GLfloat blue[] = {0.0f, 0.0f, 1.0f, 1.0f};
        glClearBufferfv(GL_COLOR, 0, blue);
        glViewport(1, 2, 3, 4);
        ASSERT_TRUE(pass_.apply(scene, s, error, &elsewhere)) << error;
        EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
        GLint bound = 0, drawn_viewport[4] = {};
        glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &bound);
        glGetIntegerv(GL_VIEWPORT, drawn_viewport);
        EXPECT_EQ(GLuint(bound), other);
        EXPECT_EQ(std::vector<int>(drawn_viewport, drawn_viewport + 4),
                  std::vector<int>({1, 2, 3, 4}));  // as the pass found it
        const std::vector<uint8_t> there = read_rgb(other, 0, 0, kOtherWidth, kOtherHeight);
        const std::vector<uint8_t> scene_after = read_rgb(framebuffer_, 0, 0, kSize, kSize);
        int differing = 0, darker = 0, outside_drawn = 0, scene_changed = 0;
        for (int y = 0; y < kOtherHeight; ++y) {
            for (int x = 0; x < kOtherWidth; ++x) {
                const uint8_t* p = &there[(size_t(y) * kOtherWidth + size_t(x)) * 3];
                const bool inside = x >= kX && x < kX + kSize && y >= kY && y < kY + kSize;
                if (!inside) {
                    outside_drawn += !(p[0] == 0 && p[1] == 0 && p[2] == 255);
                    continue;
                }
                const size_t i = (size_t(y - kY) * kSize + size_t(x - kX)) * 3;
                for (int c = 0; c < 3; ++c) differing += std::abs(p[c] - in_place[i + c]) > 1;
                darker += p[0] < (show ? 230 : 0.8f * 230);
            }
        }
        for (size_t i = 0; i < scene_after.size(); ++i)
            scene_changed += std::abs(scene_after[i] - std::lround(colour[i % 3] * 255)) > 1;
        EXPECT_EQ(differing, 0) << "show " << show;
        EXPECT_EQ(outside_drawn, 0) << "show " << show;
        EXPECT_EQ(scene_changed, 0) << "show " << show;
        EXPECT_GT(darker, 100) << "show " << show;
    }
    glDeleteFramebuffers(1, &other);
    glDeleteTextures(1, &other_texture);
}

// A style that keeps its ambient light apart writes its share in the normal's alpha: only that
// share of the colour is darkened, colour * (1 - share * (1 - open)).
TEST_F(ObscurancePassTest, OnlyTheAmbientShareOfTheColourIsDarkened) {
    build_scene({kFloor, kWall});
    const ObscuranceSettings s = settings_for(ObscuranceMode::lines9);
    const std::vector<float> whole = run(s);
    std::vector<uint8_t> normals(size_t(kSize) * kSize * 4);
    glBindTexture(GL_TEXTURE_2D, normal_);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, normals.data());
    for (size_t i = 0; i < hits_.size(); ++i) {
        if (hits_[i]) normals[i * 4 + 3] = 64;  // a quarter of the colour is ambient
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, kSize, kSize, GL_RGBA, GL_UNSIGNED_BYTE,
                    normals.data());
    const std::vector<float> quarter = run(s);
    int darkened = 0;
    for (size_t i = 0; i < whole.size(); ++i) {
        const float open = whole[i];
        EXPECT_NEAR(quarter[i], 1.0f - (64.0f / 255.0f) * (1.0f - open), 1.5f / 255.0f);
        darkened += open < 0.8f;
    }
    EXPECT_GT(darkened, 100);
}

TEST_F(ObscurancePassTest, HalfResolutionGivesTheSameVolumes) {
    build_scene({kFloor, kWall});
    ObscuranceSettings s = settings_for(ObscuranceMode::lines9);
    s.thickness = 0.0f;
    s.half_resolution = true;
    s.blur = true;
    const std::vector<float> drawn = run(s);
    const auto expected = [&](glm::vec3 p, const Hit& hit) -> std::optional<float> {
        return open_near_wall(distance_to_crease(p, hit), s.radius);
    };
    int counted = 0;
    EXPECT_LT(mean_error(drawn, expected, counted), 0.07f);
}

// area1's mip chain: every texel of level k holds the mean distance and mean squared distance
// of the 2^k x 2^k scene texels under it (sky at the moments' far distance, 4096).
TEST_F(ObscurancePassTest, AreaMomentsAtAMipLevelAreTheMeansComputedHere) {
    build_scene({kFloor, kWall});
    run(settings_for(ObscuranceMode::area1));
    ASSERT_NE(pass_.moments_texture(), 0u);
    std::vector<double> distance(hits_.size());
    for (size_t i = 0; i < hits_.size(); ++i)
        distance[i] = hits_[i] ? std::min(double(hits_[i]->distance), 4096.0) : 4096.0;
    glBindTexture(GL_TEXTURE_2D, pass_.moments_texture());
    for (int level : {0, 2, 4}) {
        const int size = kSize >> level, block = 1 << level;
        std::vector<float> moments(size_t(size) * size * 2);
        glGetTexImage(GL_TEXTURE_2D, level, GL_RG, GL_FLOAT, moments.data());
        double worst_mean = 0.0, worst_variance = 0.0;
        for (int y = 0; y < size; ++y) {
            for (int x = 0; x < size; ++x) {
                double sum = 0.0, sum2 = 0.0;
                for (int v = 0; v < block; ++v) {
                    for (int u = 0; u < block; ++u) {
                        const double t =
                            distance[size_t(y * block + v) * kSize + size_t(x * block + u)];
                        sum += t;
                        sum2 += t * t;
                    }
                }
                const double n = double(block) * block, mean = sum / n;
                const double variance = sum2 / n - mean * mean;
                const size_t i = (size_t(y) * size + size_t(x)) * 2;
                const double gpu_variance =
                    double(moments[i + 1]) - double(moments[i]) * moments[i];
                worst_mean = std::max(worst_mean, std::abs(moments[i] - mean) / mean);
                worst_variance = std::max(worst_variance, std::abs(gpu_variance - variance) /
                                                              std::max(variance, 4096.0 * 4.0));
            }
        }
        EXPECT_LT(worst_mean, 2e-4) << "level " << level;
        EXPECT_LT(worst_variance, 1e-3) << "level " << level;
    }
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// A scene that changes size (a resized window, a smaller viewport) gets targets and moments of
// its own size: the floor stays open in every mode, before and after, and GL reports nothing.
TEST_F(ObscurancePassTest, ASceneOfAnotherSizeGetsTargetsOfItsSize) {
    build_scene({kFloor});
    for (ObscuranceMode mode : kModes) {
        if (mode == ObscuranceMode::reference) continue;  // slow, and no targets of its own
        ObscuranceSettings s = settings_for(mode);
        s.blur = true;
        obscurance::SceneTextures scene;
        scene.framebuffer = framebuffer_;
        scene.depth_texture = depth_;
        scene.normal_texture = normal_;
        std::copy_n(glm::value_ptr(projection_), 16, scene.projection);
        for (int side : {kSize, kSize / 2 + 3, kSize}) {
            scene.width = scene.height = side;
            std::string error;
            EXPECT_TRUE(pass_.apply(scene, s, error)) << error;
            EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR)) << obscurance::obscurance_mode_name(mode);
            GLint width = 0;
            glBindTexture(GL_TEXTURE_2D, pass_.open_texture());
            glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &width);
            EXPECT_EQ(width, side) << obscurance::obscurance_mode_name(mode);
        }
        int counted = 0;
        const float error = mean_error(
            run(s), [](glm::vec3, const Hit&) { return 1.0f; }, counted);
        EXPECT_LT(error, 0.04f) << obscurance::obscurance_mode_name(mode);
    }
}

// vo_compute: the estimate and the blur as compute programs give the picture the full-screen
// triangles give, in every mode, at full and half resolution (the context here has GL 4.5),
// also where the size is no multiple of the compute groups' (8).
TEST_F(ObscurancePassTest, ComputeAndFragmentStagesGiveTheSamePicture) {
    build_scene({kFloor, kWall});
    for (ObscuranceMode mode : kModes) {
        if (mode == ObscuranceMode::reference) continue;  // slow; the same estimate as lines
        for (auto [half, side] : {std::pair{false, kSize}, std::pair{true, kSize},
                                  std::pair{false, kSize - 27}, std::pair{true, kSize - 27}}) {
            ObscuranceSettings s = settings_for(mode);
            s.blur = true;
            s.half_resolution = half;
            s.compute = obscurance::ComputeUse::off;
            const std::vector<float> fragment = run(s, side);
            EXPECT_EQ(pass_.ran(), StagePath::fragment);
            s.compute = obscurance::ComputeUse::on;
            const std::vector<float> compute = run(s, side);
            EXPECT_EQ(pass_.ran(), StagePath::compute);
            float worst = 0.0f, darkest = 1.0f;
            for (size_t i = 0; i < compute.size(); ++i) {
                worst = std::max(worst, std::abs(compute[i] - fragment[i]));
                darkest = std::min(darkest, compute[i]);
            }
            // One step of the 8-bit colour: the two paths only round differently.
            EXPECT_LE(worst, 1.5f / 255.0f)
                << obscurance::obscurance_mode_name(mode) << " half " << half << " side " << side;
            EXPECT_LT(darkest, 0.9f) << obscurance::obscurance_mode_name(mode) << half;
        }
    }
}

// vo_compute 2: a trial runs both ways in turn (compute first) and then keeps the one whose
// median GPU time (estimate and blur) was lower; the picture is the same in every frame,
// whichever way it took. Another mode starts another trial.
TEST_F(ObscurancePassTest, TheFasterWayIsChosenAndThePictureStaysTheSame) {
    build_scene({kFloor, kWall});
    ObscuranceSettings s = settings_for(ObscuranceMode::lines5);
    s.blur = true;
    s.compute = obscurance::ComputeUse::off;
    const std::vector<float> expected = run(s);
    s.compute = obscurance::ComputeUse::fastest;
    for (ObscuranceMode mode : {ObscuranceMode::lines5, ObscuranceMode::points12}) {
        s.mode = mode;
        const int decisions = pass_.decisions();
        // run reads the picture back, so a trial frame's times are there by the next frame.
        int frames = 0;
        while (frames < StageTrial::kFrames + 4) {
            const int frame = frames++;
            const std::vector<float> drawn = run(s);
            if (mode == ObscuranceMode::lines5) {
                float worst = 0.0f;
                for (size_t i = 0; i < drawn.size(); ++i) {
                    worst = std::max(worst, std::abs(drawn[i] - expected[i]));
                }
                EXPECT_LE(worst, 1.5f / 255.0f) << "frame " << frame;
            }
            if (frame < StageTrial::kFrames) {
                EXPECT_EQ(pass_.ran(), StageTrial::path_of_frame(frame));
            }
            if (pass_.trial().decided()) break;
        }
        ASSERT_TRUE(pass_.trial().decided()) << obscurance::obscurance_mode_name(mode);
        EXPECT_EQ(pass_.decisions(), decisions + 1);
        EXPECT_GT(frames, StageTrial::kFrames);  // decided in the frame after the last trial one
        run(s);
        for (TimedStage stage : {TimedStage::estimate, TimedStage::blur}) {
            EXPECT_GT(pass_.trial().median(stage, StagePath::fragment), 0u);
            EXPECT_GT(pass_.trial().median(stage, StagePath::compute), 0u);
        }
        const uint64_t fragment = pass_.trial().median(StagePath::fragment);
        const uint64_t compute = pass_.trial().median(StagePath::compute);
        EXPECT_EQ(pass_.ran(), fragment < compute ? StagePath::fragment : StagePath::compute);
    }
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// The stage markers (the engine's per-stage timer queries) open and close around each stage
// the settings run, in order: area1's moments first, no blur when it is off or for the reference.
TEST_F(ObscurancePassTest, EachStageIsMarkedInTheOrderItRuns) {
    build_scene({kFloor, kWall});
    std::vector<std::string> marks;
    obscurance::PassMarkers markers;
    markers.begin = [](void* context, const char* stage) {
        static_cast<std::vector<std::string>*>(context)->push_back(stage);
    };
    markers.end = [](void* context) {
        static_cast<std::vector<std::string>*>(context)->push_back("end");
    };
    markers.context = &marks;
    pass_.set_markers(markers);
    const std::vector<std::string> estimate = {"vo_estimate", "end"};
    const std::vector<std::string> blur = {"vo_blur", "end"};
    const std::vector<std::string> composite = {"vo_composite", "end"};
    auto joined = [](std::initializer_list<std::vector<std::string>> parts) {
        std::vector<std::string> all;
        for (const auto& part : parts) all.insert(all.end(), part.begin(), part.end());
        return all;
    };
    struct Case {
        ObscuranceMode mode;
        bool blur;
        std::vector<std::string> expected;
    };
    const Case cases[] = {
        {ObscuranceMode::lines5, true, joined({estimate, blur, composite})},
        {ObscuranceMode::points12, false, joined({estimate, composite})},
        {ObscuranceMode::area1, true, joined({{"vo_moments", "end"}, estimate, blur, composite})},
        {ObscuranceMode::reference, true, joined({estimate, composite})},
    };
    for (const Case& c : cases) {
        marks.clear();
        ObscuranceSettings s = settings_for(c.mode);
        s.blur = c.blur;
        run(s);
        EXPECT_EQ(marks, c.expected) << obscurance::obscurance_mode_name(c.mode);
    }
}

// vo_sample_count: the paper's counts' neighbours run through the same estimate (rebuilt for
// their count) and measure the crease as well; a count without a table takes the mode's own.
TEST_F(ObscurancePassTest, TheNeighbouringCountsMeasureTheCreaseToo) {
    build_scene({kFloor, kWall});
    ObscuranceSettings s = settings_for(ObscuranceMode::lines5);
    s.thickness = 0.0f;
    const auto expected = [&](glm::vec3 p, const Hit& hit) -> std::optional<float> {
        return open_near_wall(distance_to_crease(p, hit), s.radius);
    };
    const std::vector<float> own = run(s);
    for (int count : {4, 6, 8, 10, 11, 13, 32, 34}) {
        s.mode = count <= 10 ? ObscuranceMode::lines5 : ObscuranceMode::points12;
        s.sample_count = count;
        ASSERT_EQ(obscurance::effective_sample_count(s), count);
        int counted = 0;
        EXPECT_LT(mean_error(run(s), expected, counted), 0.07f) << count;
    }
    s.mode = ObscuranceMode::lines5;
    s.sample_count = 7;  // no table of 7 lines
    EXPECT_EQ(obscurance::effective_sample_count(s), 5);
    EXPECT_EQ(run(s), own);
    s.sample_method = obscurance::SampleMethod::poisson;
    s.sample_count = 4;  // neighbours are electrostatic only
    EXPECT_EQ(obscurance::effective_sample_count(s), 5);
}

TEST_F(ObscurancePassTest, TheModeNamesRoundTrip) {
    for (ObscuranceMode mode : kModes) {
        EXPECT_EQ(obscurance::parse_obscurance_mode(obscurance::obscurance_mode_name(mode)), mode);
    }
    EXPECT_FALSE(obscurance::parse_obscurance_mode("lines6"));
    EXPECT_FALSE(obscurance::parse_obscurance_mode(""));
}

}  // namespace
}  // namespace nq::npr::test

// The technical style's planar shadows: the math of nprlib/technical/planar_shadow (finding the
// floor with the engine's trace, projecting along the light, umbra and penumbra passes, low
// lights) checked against independent ray-plane geometry, and ShadowDrawer's pictures on Mesa
// llvmpipe: every floor pixel is predicted here by casting a ray from it toward the light.
#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <tuple>
#include <vector>

#include "abi/frame_view.h"
#include "classic/alias_model_gpu.h"
#include "classic/classic_pass.h"
#include "gl/program.h"
#include "support/nprlib_test_support.h"
#include "technical/alias_edge_mesh.h"
#include "technical/alias_face_drawer.h"
#include "technical/alias_pose.h"
#include "technical/planar_shadow.h"
#include "technical/shadow_drawer.h"
#include "technical/skin_tones.h"
#include "technical/technical_models.h"
#include "technical/technical_settings.h"

namespace nq::npr::test {
namespace {

using technical::build_shadow_passes;
using technical::find_shadow_plane;
using technical::ShadowPasses;
using technical::ShadowPlane;
using technical::ShadowSettings;

// ------------------------------------------------------------------ independent geometry

// Where the ray origin + t * direction meets the plane dot(n, x) = d.
glm::vec3 ray_plane(glm::vec3 origin, glm::vec3 direction, glm::vec3 n, float d) {
    const float t = (d - glm::dot(n, origin)) / glm::dot(n, direction);
    return origin + t * direction;
}

glm::vec3 apply(const glm::mat4& m, glm::vec3 p) {
    const glm::vec4 q = m * glm::vec4(p, 1.0f);
    return glm::vec3(q) / q.w;
}

void expect_vec_near(glm::vec3 actual, glm::vec3 expected, float tolerance) {
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
    EXPECT_NEAR(actual.z, expected.z, tolerance);
}

ShadowPlane plane_of(glm::vec3 normal, float distance) {
    ShadowPlane plane;
    plane.found = true;
    plane.normal = glm::normalize(normal);
    plane.distance = distance;
    return plane;
}

ShadowSettings hard_shadows() {
    ShadowSettings s;
    s.penumbra = false;
    return s;
}

const glm::vec3 kSamplePoints[] = {{10, -4, 60}, {-30, 25, 12}, {0, 0, 100}, {7, 7, 7}};

// ------------------------------------------------------------------ projection math

TEST(PlanarShadowMath, HardShadowProjectsEachPointAlongTheLight) {
    const ShadowPlane plane = plane_of({0.2f, -0.1f, 1.0f}, 5.0f);
    const glm::vec3 light = glm::normalize(glm::vec3(0.5f, 0.3f, 1.0f));
    const ShadowSettings settings = hard_shadows();
    const ShadowPasses passes = build_shadow_passes(plane, light, {0, 0, 30}, settings);
    ASSERT_EQ(passes.count, 1);
    EXPECT_FLOAT_EQ(passes.pass[0].alpha, settings.alpha);
    for (const glm::vec3& p : kSamplePoints) {
        // The shadow of p: walk from p away from the light until the plane.
        const glm::vec3 expected = ray_plane(p, -light, plane.normal, plane.distance);
        expect_vec_near(apply(passes.pass[0].world_to_plane, p), expected, 1e-3f);
    }
    // A point of the plane is its own shadow.
    const glm::vec3 on_plane = ray_plane({3, 4, 50}, {0, 0, -1}, plane.normal, plane.distance);
    expect_vec_near(apply(passes.pass[0].world_to_plane, on_plane), on_plane, 1e-3f);
}

TEST(PlanarShadowMath, UmbraIsScaledAboutTheShadowOfTheCentre) {
    const ShadowPlane plane = plane_of({0, 0, 1}, -20.0f);
    const glm::vec3 light = glm::normalize(glm::vec3(-0.4f, 0.2f, 1.0f));
    const glm::vec3 centre(5, 6, 40);
    ShadowSettings settings;
    settings.umbra_scale = 0.8f;
    const ShadowPasses passes = build_shadow_passes(plane, light, centre, settings);
    ASSERT_EQ(passes.count, 3);
    EXPECT_FLOAT_EQ(passes.pass[0].alpha, settings.alpha);
    const glm::vec3 centre_shadow = ray_plane(centre, -light, plane.normal, plane.distance);
    for (const glm::vec3& p : kSamplePoints) {
        const glm::vec3 hard = ray_plane(p, -light, plane.normal, plane.distance);
        const glm::vec3 expected = centre_shadow + 0.8f * (hard - centre_shadow);
        expect_vec_near(apply(passes.pass[0].world_to_plane, p), expected, 1e-3f);
    }
}

TEST(PlanarShadowMath, PenumbraPassesAreShiftedSidewaysToTheLight) {
    const ShadowPlane plane = plane_of({0, 0, 1}, 0.0f);
    const glm::vec3 light = glm::normalize(glm::vec3(1.0f, 1.0f, 2.0f));
    ShadowSettings settings;
    settings.penumbra_offset = 6.0f;
    const ShadowPasses passes = build_shadow_passes(plane, light, {0, 0, 30}, settings);
    ASSERT_EQ(passes.count, 3);
    // The light comes along the plane from (1, 1): sideways is +-(1, -1) / sqrt 2.
    const glm::vec3 side = glm::normalize(glm::vec3(1, -1, 0));
    glm::vec3 shifts[2];
    for (int k = 0; k < 2; ++k) {
        const technical::ShadowPass& pass = passes.pass[1 + k];
        EXPECT_FLOAT_EQ(pass.alpha, settings.penumbra_alpha);
        const glm::vec3 p = kSamplePoints[k];
        shifts[k] = apply(pass.world_to_plane, p) - ray_plane(p, -light, plane.normal, 0.0f);
        EXPECT_NEAR(std::abs(glm::dot(shifts[k], side)), 6.0f, 1e-3f);
        EXPECT_NEAR(glm::length(shifts[k]), 6.0f, 1e-3f);
    }
    expect_vec_near(shifts[0], -shifts[1], 1e-3f);  // one to each side
}

TEST(PlanarShadowMath, OverheadLightStillGetsTwoPenumbraPasses) {
    const ShadowPlane plane = plane_of({0, 0, 1}, 0.0f);
    ShadowSettings settings;
    const ShadowPasses passes = build_shadow_passes(plane, {0, 0, 1}, {0, 0, 30}, settings);
    ASSERT_EQ(passes.count, 3);
    const glm::vec3 p(3, 4, 50);
    for (int k = 1; k < 3; ++k) {
        const glm::vec3 shift = apply(passes.pass[k].world_to_plane, p) - glm::vec3(3, 4, 0);
        EXPECT_NEAR(glm::length(shift), settings.penumbra_offset, 1e-3f);
        EXPECT_NEAR(shift.z, 0.0f, 1e-4f);
    }
}

TEST(PlanarShadowMath, LowLightIsSteepenedToFifteenDegrees) {
    const ShadowPlane plane = plane_of({0, 0, 1}, 0.0f);
    const float elevation = glm::radians(5.0f);
    const glm::vec3 light(std::cos(elevation) * 0.6f, std::cos(elevation) * 0.8f,
                          std::sin(elevation));
    const ShadowPasses passes = build_shadow_passes(plane, light, {0, 0, 0}, hard_shadows());
    ASSERT_EQ(passes.count, 1);
    // A point 10 units up: its shadow lies away from the light, 10 / tan(15 deg) along the
    // floor, in the light's own direction along the floor.
    const glm::vec3 shadow = apply(passes.pass[0].world_to_plane, {0, 0, 10});
    EXPECT_NEAR(shadow.z, 0.0f, 1e-4f);
    EXPECT_NEAR(glm::length(shadow), 10.0f / std::tan(glm::radians(15.0f)), 1e-2f);
    expect_vec_near(glm::normalize(shadow), {-0.6f, -0.8f, 0.0f}, 1e-4f);
}

TEST(PlanarShadowMath, SteepEnoughLightIsKept) {
    const ShadowPlane plane = plane_of({0, 0, 1}, 0.0f);
    const float elevation = glm::radians(20.0f);
    const glm::vec3 light(std::cos(elevation), 0.0f, std::sin(elevation));
    const ShadowPasses passes = build_shadow_passes(plane, light, {0, 0, 0}, hard_shadows());
    ASSERT_EQ(passes.count, 1);
    const glm::vec3 shadow = apply(passes.pass[0].world_to_plane, {0, 0, 10});
    EXPECT_NEAR(shadow.x, -10.0f / std::tan(elevation), 1e-3f);
}

TEST(PlanarShadowMath, NoShadowWithoutPlaneOrFromBelowOrWhenDisabled) {
    const ShadowPlane floor = plane_of({0, 0, 1}, 0.0f);
    const glm::vec3 centre(0, 0, 20);
    ShadowSettings settings;
    EXPECT_EQ(build_shadow_passes(floor, {0.3f, 0, -1}, centre, settings).count, 0);
    EXPECT_EQ(build_shadow_passes(floor, {1, 0, 0}, centre, settings).count, 0);
    EXPECT_EQ(build_shadow_passes(floor, {0, 0, 0}, centre, settings).count, 0);
    EXPECT_EQ(build_shadow_passes(ShadowPlane{}, {0, 0, 1}, centre, settings).count, 0);
    settings.enabled = false;
    EXPECT_EQ(build_shadow_passes(floor, {0, 0, 1}, centre, settings).count, 0);
}

// ------------------------------------------------------------------ find_shadow_plane

struct FakeWorld {
    nqr_trace result{};
    glm::vec3 start{0}, end{0};
    int calls = 0;
};

FakeWorld& fake_world() {
    static FakeWorld world;  // the engine's trace is a plain C function pointer
    return world;
}

void fake_trace(void*, const float start[3], const float end[3], nqr_trace* out) {
    FakeWorld& world = fake_world();
    ++world.calls;
    world.start = glm::make_vec3(start);
    world.end = glm::make_vec3(end);
    const uint32_t size = out->size;
    *out = world.result;
    out->size = size;
}

// A world whose trace hits the plane dot(normal, x) = dist at fraction 0.25.
nqr_engine engine_with_floor(glm::vec3 normal, float dist, glm::vec3 hit) {
    FakeWorld& world = fake_world();
    world = FakeWorld{};
    world.result.fraction = 0.25f;
    std::copy_n(&normal.x, 3, world.result.plane_normal);
    world.result.plane_dist = dist;
    std::copy_n(&hit.x, 3, world.result.end);
    nqr_engine engine{};
    engine.size = sizeof(nqr_engine);
    engine.trace = fake_trace;
    return engine;
}

// A model that is mostly fullbright colours (224..254) glows: it is a light, not a caster.
TEST(LightModels, FullbrightShareOfTheFirstSkinCountsFullbrightPixels) {
    AliasBuilder b;
    b.add_box_pose({0, 0, 0}, {16, 16, 16});
    b.skin.assign(64, 15);
    EXPECT_EQ(technical::fullbright_share(*b.build()), 0.0f);
    std::fill(b.skin.begin(), b.skin.begin() + 16, 224);       // the first fullbright colour
    std::fill(b.skin.begin() + 16, b.skin.begin() + 24, 254);  // and the last
    std::fill(b.skin.begin() + 24, b.skin.begin() + 32, 255);  // transparent, not bright
    EXPECT_FLOAT_EQ(technical::fullbright_share(*b.build()), 24.0f / 64.0f);
    EXPECT_LT(technical::fullbright_share(*b.build()), technical::kLightSkinShare);
    b.skin.assign(64, 240);
    EXPECT_EQ(technical::fullbright_share(*b.build()), 1.0f);
}

TEST(FindShadowPlane, TracesStraightDownAndReturnsThePlaneHit) {
    const nqr_engine engine = engine_with_floor({0, 0.6f, 0.8f}, -12.0f, {5, 6, -20});
    const ShadowPlane plane = find_shadow_plane(engine, {5, 6, 40}, 300.0f);
    EXPECT_EQ(fake_world().calls, 1);
    expect_vec_near(fake_world().start, {5, 6, 40}, 0.0f);
    expect_vec_near(fake_world().end, {5, 6, -260}, 0.0f);
    ASSERT_TRUE(plane.found);
    expect_vec_near(plane.normal, {0, 0.6f, 0.8f}, 1e-6f);
    EXPECT_FLOAT_EQ(plane.distance, -12.0f);
    expect_vec_near(plane.hit, {5, 6, -20}, 0.0f);
}

TEST(FindShadowPlane, NothingHitStartInSolidOrNoTraceFindNothing) {
    nqr_engine engine = engine_with_floor({0, 0, 1}, 0.0f, {0, 0, 0});
    fake_world().result.fraction = 1.0f;
    EXPECT_FALSE(find_shadow_plane(engine, {0, 0, 40}, 100.0f).found);
    fake_world().result.fraction = 0.0f;
    fake_world().result.start_solid = 1;
    EXPECT_FALSE(find_shadow_plane(engine, {0, 0, 40}, 100.0f).found);
    fake_world().result.start_solid = 0;
    EXPECT_TRUE(find_shadow_plane(engine, {0, 0, 40}, 100.0f).found);
    engine.trace = nullptr;
    EXPECT_FALSE(find_shadow_plane(engine, {0, 0, 40}, 100.0f).found);
}

// ------------------------------------------------------------------ pictures

const Rgb kFloor{200, 180, 160};
const Rgb kSky{0, 0, 0};
constexpr float kFloorHalf = 100.0f;  // the floor quad spans [-100, 100]^2 at z = 0

struct Box {
    glm::vec3 lo, hi;
    Box grown(float by) const { return {lo - by, hi + by}; }
};

// Slab test: does origin + t * direction (t > 0) pass through the box?
bool ray_hits_box(glm::vec3 origin, glm::vec3 direction, const Box& box) {
    float near_t = 0.0f, far_t = 1e9f;
    for (int axis = 0; axis < 3; ++axis) {
        if (std::abs(direction[axis]) < 1e-9f) {
            if (origin[axis] < box.lo[axis] || origin[axis] > box.hi[axis]) return false;
            continue;
        }
        float t0 = (box.lo[axis] - origin[axis]) / direction[axis];
        float t1 = (box.hi[axis] - origin[axis]) / direction[axis];
        if (t0 > t1) std::swap(t0, t1);
        near_t = std::max(near_t, t0);
        far_t = std::min(far_t, t1);
    }
    return near_t <= far_t;
}

// Whether a floor point is in the hard shadow of the boxes: yes, no, or too close to call.
enum class Cover { yes, no, unsure };

// World units: pixel centres are classified exactly, this only absorbs rounding.
constexpr float kMargin = 1.0f;

Cover shadowed(glm::vec3 floor_point, glm::vec3 light, const std::vector<Box>& boxes) {
    bool inside = false, near_edge = false;
    for (const Box& box : boxes) {
        inside |= ray_hits_box(floor_point, light, box.grown(-kMargin));
        near_edge |= ray_hits_box(floor_point, light, box.grown(kMargin));
    }
    return inside ? Cover::yes : near_edge ? Cover::unsure : Cover::no;
}

// Quake's winding: each face clockwise seen from outside.
void add_cube(AliasBuilder& b, glm::ivec3 lo, glm::ivec3 hi) {
    if (b.poses.empty()) b.poses.emplace_back();
    const int first = static_cast<int>(b.poses[0].size());
    for (int i = 0; i < 8; ++i) {
        b.poses[0].push_back({static_cast<uint8_t>(i & 1 ? hi.x : lo.x),
                              static_cast<uint8_t>(i & 2 ? hi.y : lo.y),
                              static_cast<uint8_t>(i & 4 ? hi.z : lo.z)});
        b.st.push_back({0, 4, 4});
    }
    // Corner quads counter-clockwise from outside (bit 0: x, bit 1: y, bit 2: z), reversed.
    const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                             {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& f : faces) {
        b.triangles.push_back({1, first + f[0], first + f[2], first + f[1]});
        b.triangles.push_back({1, first + f[0], first + f[3], first + f[2]});
    }
}

// The floor: a plain depth-writing quad in one colour, as the world drawer would leave it.
class FloorQuad {
  public:
    bool init(gl::ObjectTracker* tracker, std::string& error) {
        static constexpr char kVertex[] = R"(#version 330 core
layout(location = 0) in vec3 a_position;
uniform mat4 u_view_projection;
void main() { gl_Position = u_view_projection * vec4(a_position, 1.0); })";
        static constexpr char kFragment[] = R"(#version 330 core
uniform vec3 u_color;
layout(location = 0) out vec4 o_color;
void main() { o_color = vec4(u_color, 1.0); })";
        gl::ProgramBuild build = gl::Program::build({"test floor", kVertex, kFragment}, tracker);
        if (!build.ok()) {
            error = build.error;
            return false;
        }
        program_ = std::move(build.program);
        const float h = kFloorHalf;
        const float corners[] = {-h, -h, 0, h, -h, 0, -h, h, 0, h, h, 0};
        vertex_array_ = gl::VertexArray::create(tracker);
        buffer_ = gl::Buffer::create(tracker);
        glBindVertexArray(vertex_array_.id());
        glBindBuffer(GL_ARRAY_BUFFER, buffer_.id());
        glBufferData(GL_ARRAY_BUFFER, sizeof(corners), corners, GL_STATIC_DRAW);
        glEnableVertexAttribArray(0);
        glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
        glBindVertexArray(0);
        glBindBuffer(GL_ARRAY_BUFFER, 0);
        return true;
    }

    void draw(const npr::FrameView& view) {
        program_.use();
        glUniformMatrix4fv(program_.location("u_view_projection"), 1, GL_FALSE,
                           glm::value_ptr(view.view_projection));
        glUniform3f(program_.location("u_color"), kFloor.r / 255.0f, kFloor.g / 255.0f,
                    kFloor.b / 255.0f);
        glBindVertexArray(vertex_array_.id());
        glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
        glBindVertexArray(0);
        glUseProgram(0);
    }

    void reset() {
        program_.reset();
        vertex_array_.reset();
        buffer_.reset();
    }

  private:
    gl::Program program_;
    gl::VertexArray vertex_array_;
    gl::Buffer buffer_;
};

// From (-50, 0, 45) looking down at (0, 0, 8), a 50 degree field of view: the model and the
// shadow it casts toward the camera fill much of the picture.
nqr_camera oblique_camera() {
    const float pitch = glm::degrees(std::atan2(45.0f - 8.0f, 50.0f));
    return make_camera({-50.0f, 0.0f, 45.0f}, {pitch, 0.0f, 0.0f}, 50.0f);
}

// The floor point seen through pixel (x, y), or nothing (sky, beyond the floor quad).
bool floor_under_pixel(const nqr_camera& camera, int x, int y, glm::vec3& out) {
    const glm::mat4 inverse = glm::inverse(glm::make_mat4(camera.view_projection));
    const float ndc_x = (x + 0.5f) / (kSize / 2.0f) - 1.0f;
    const float ndc_y = (y + 0.5f) / (kSize / 2.0f) - 1.0f;
    const glm::vec3 a = apply(inverse, {ndc_x, ndc_y, -1.0f});
    const glm::vec3 b = apply(inverse, {ndc_x, ndc_y, 1.0f});
    if (b.z >= a.z) return false;  // looking up
    out = ray_plane(a, b - a, {0, 0, 1}, 0.0f);
    return std::abs(out.x) < kFloorHalf - kMargin && std::abs(out.y) < kFloorHalf - kMargin;
}

glm::vec3 camera_eye(const nqr_camera& camera) {
    return glm::make_vec3(camera.origin);
}

Rgb darkened(Rgb floor, float keep) {
    return {static_cast<int>(std::lround(floor.r * keep)),
            static_cast<int>(std::lround(floor.g * keep)),
            static_cast<int>(std::lround(floor.b * keep))};
}

class TechnicalShadowsTest : public GlSuiteTest<TechnicalShadowsTest> {
  protected:
    void SetUp() override {
        GlSuiteTest::SetUp();
        if (HasFatalFailure()) return;
        std::string error;
        ASSERT_TRUE(floor_.init(&tracker_, error)) << error;
        ASSERT_TRUE(faces_.init(&tracker_, error)) << error;
        ASSERT_TRUE(shadows_.init(&tracker_, error)) << error;
        engine_ = engine_with_floor({0, 0, 1}, 0.0f, {0, 0, 0.03125f});
        light_from(light_);
    }

    void TearDown() override {
        gpu_.reset();
        floor_.reset();
        faces_.reset();
        shadows_.reset();
        EXPECT_EQ(tracker_.total_live(), 0);
    }

    // The model's cubes, in packed units (scale 1, origin -8: the first cube is [-8, 8]^3),
    // drawn at `height` above the floor.
    void upload_cubes(std::vector<std::pair<glm::ivec3, glm::ivec3>> cubes, float height) {
        AliasBuilder& b = builder_;
        for (const auto& [lo, hi] : cubes) {
            add_cube(b, lo, hi);
            boxes_.push_back({glm::vec3(lo) - 8.0f + glm::vec3(0, 0, height),
                              glm::vec3(hi) - 8.0f + glm::vec3(0, 0, height)});
        }
        b.origin = glm::vec3(-8.0f);
        b.skin.assign(64, 150);
        std::string error;
        gpu_ = classic::AliasModelGpu::create(&tracker_, *b.build(), palette_.data(), error);
        ASSERT_TRUE(gpu_) << error;
        mesh_ = technical::AliasEdgeMesh::create(*b.build(), error);
        ASSERT_TRUE(mesh_) << error;
        entity_ = make_entity(1, glm::translate(glm::mat4(1.0f), {0.0f, 0.0f, height}));
        entity_.light = &entity_light_;
        light_from(light_);
    }

    void light_from(glm::vec3 toward_light) {
        light_ = glm::normalize(toward_light);
        std::copy_n(&light_.x, 3, entity_light_.direction);
    }

    npr::FrameView view() {
        npr::FrameView view;
        EXPECT_TRUE(npr::read_frame_view(frame_.build(oblique_camera(), 0), view));
        return view;
    }

    void draw_floor() {
        gl_->clear(kSky);
        classic::begin_classic_pass();
        floor_.draw(view());
    }

    // Adds `entity`'s shadow (the model's pose blended here) to the frame's batch.
    void add_shadow(const nqr_entity& entity, const ShadowSettings& settings) {
        const glm::vec3 origin = glm::make_vec3(entity.origin);
        const ShadowPlane plane = find_shadow_plane(engine_, origin, settings.max_drop);
        const ShadowPasses passes = build_shadow_passes(plane, light_, origin, settings);
        std::vector<glm::vec3> pose(mesh_->vertex_count());
        technical::blend_alias_pose(gpu_->model(), entity, pose.data());
        shadows_.add_entity(view(), entity, *mesh_, pose.data(), passes);
    }

    void draw_shadow(const ShadowSettings& settings) {
        add_shadow(entity_, settings);
        shadows_.draw(settings);
    }

    void draw_faces() {
        const classic::SkinImageGpu* image = gpu_->skin_image(0, 0);
        const glm::vec3 kd =
            technical::sample_skin(gpu_->model(), gpu_->skin_pixels(0, 0), entity_, palette_.data())
                .average;
        faces_.draw_entity(view(), entity_, *gpu_, image->base.id(), 0, kd, {});
    }

    // The renderer's order: world, shadows, faces.
    std::vector<Rgb> render(const ShadowSettings* settings, bool with_faces = true) {
        draw_floor();
        if (settings) {
            shadows_.begin_frame();
            draw_shadow(*settings);
        }
        if (with_faces) draw_faces();
        EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
        return gl_->pixels();
    }

    // Whether the camera sees the floor at pixel (x, y) (not the model, not the sky); `point`
    // is where.
    bool floor_visible(int x, int y, glm::vec3& point) const {
        const nqr_camera camera = oblique_camera();
        if (!floor_under_pixel(camera, x, y, point)) return false;
        const glm::vec3 eye = camera_eye(camera);
        for (const Box& box : boxes_) {
            if (ray_hits_box(eye, point - eye, box.grown(kMargin))) return false;
        }
        return true;
    }

    // The floor colour expected at `point` with each pass's coverage predicted from the boxes:
    // the umbra pass (penumbra on) is the hard shadow scaled about the centre's shadow, the
    // penumbra passes the hard shadow shifted sideways. False when some pass is too close to call.
    bool expected_floor(glm::vec3 point, const ShadowSettings& s, Rgb& out, int& passes) const {
        const glm::vec3 centre = glm::make_vec3(entity_.origin);
        const glm::vec3 centre_shadow = ray_plane(centre, -light_, {0, 0, 1}, 0.0f);
        const glm::vec3 side = glm::normalize(glm::cross(glm::vec3(0, 0, 1), light_));
        std::vector<std::pair<glm::vec3, float>> preimages;  // floor point of the hard shadow
        if (!s.penumbra) {
            preimages.push_back({point, s.alpha});
        } else {
            preimages.push_back({centre_shadow + (point - centre_shadow) / s.umbra_scale, s.alpha});
            preimages.push_back({point - s.penumbra_offset * side, s.penumbra_alpha});
            preimages.push_back({point + s.penumbra_offset * side, s.penumbra_alpha});
        }
        float keep = 1.0f;
        passes = 0;
        for (const auto& [preimage, alpha] : preimages) {
            const Cover cover = shadowed(preimage, light_, boxes_);
            if (cover == Cover::unsure) return false;
            if (cover == Cover::yes) {
                keep *= 1.0f - alpha;
                ++passes;
            }
        }
        out = darkened(kFloor, keep);
        return true;
    }

    struct FloorCheck {
        int checked = 0, wrong = 0;
        std::array<int, 4> pixels_by_passes{};  // pixel counts by how many passes darkened them
        Rgb first_wrong, first_expected;
    };

    FloorCheck check_floor(const std::vector<Rgb>& image, const ShadowSettings& s) const {
        FloorCheck check;
        for (int y = 0; y < kSize; ++y) {
            for (int x = 0; x < kSize; ++x) {
                glm::vec3 point;
                Rgb expected;
                int passes = 0;
                if (!floor_visible(x, y, point) || !expected_floor(point, s, expected, passes)) {
                    continue;
                }
                ++check.checked;
                ++check.pixels_by_passes[passes];
                if (!near(image[y * kSize + x], expected, 3)) {
                    if (check.wrong++ == 0) {
                        check.first_wrong = image[y * kSize + x];
                        check.first_expected = expected;
                    }
                }
            }
        }
        return check;
    }

    std::array<uint8_t, 768> palette_ = make_test_palette();
    gl::ObjectTracker tracker_;
    FloorQuad floor_;
    technical::AliasFaceDrawer faces_;
    technical::ShadowDrawer shadows_;
    nqr_engine engine_{};
    AliasBuilder builder_;
    std::unique_ptr<classic::AliasModelGpu> gpu_;
    std::unique_ptr<technical::AliasEdgeMesh> mesh_;
    std::vector<Box> boxes_;
    nqr_entity entity_ = make_entity(1);
    nqr_entity_light entity_light_ = make_light();                   // entity_.light points here
    glm::vec3 light_ = glm::normalize(glm::vec3(0.6f, 0.0f, 1.0f));  // shadow toward the eye
    TestFrame frame_;
};

// Non-floor-coloured pixels where the floor is seen, by colour.
std::map<std::tuple<int, int, int>, int> shadow_colours(const std::vector<Rgb>& image,
                                                        const std::vector<Rgb>& unshadowed) {
    std::map<std::tuple<int, int, int>, int> colours;
    for (size_t i = 0; i < image.size(); ++i) {
        if (unshadowed[i] == kFloor && image[i] != kFloor) {
            ++colours[{image[i].r, image[i].g, image[i].b}];
        }
    }
    return colours;
}

TEST_F(TechnicalShadowsTest, HardShadowDarkensTheFloorWhereTheModelBlocksTheLight) {
    upload_cubes({{{0, 0, 0}, {16, 16, 16}}}, 16.0f);
    const ShadowSettings s = hard_shadows();
    const std::vector<Rgb> image = render(&s);
    gl_->dump_if_requested("technical_shadow_hard");
    const FloorCheck check = check_floor(image, s);
    EXPECT_EQ(check.wrong, 0) << check.first_wrong << " expected " << check.first_expected;
    EXPECT_GT(check.pixels_by_passes[1], 60);    // shadow seen
    EXPECT_GT(check.pixels_by_passes[0], 3000);  // plain floor seen
}

TEST_F(TechnicalShadowsTest, OverlappingPartsOfOneModelDarkenEachPixelOnce) {
    // Two interpenetrating cubes in one mesh: flattened, their faces cover much of the shadow
    // three or four times over.
    upload_cubes({{{0, 0, 0}, {16, 16, 16}}, {{8, 6, 4}, {24, 22, 20}}}, 14.0f);
    const ShadowSettings s = hard_shadows();
    const std::vector<Rgb> image = render(&s);
    const FloorCheck check = check_floor(image, s);
    EXPECT_EQ(check.wrong, 0) << check.first_wrong << " expected " << check.first_expected;
    EXPECT_GT(check.pixels_by_passes[1], 100);
    // Every darkened floor pixel, edges included, has the one shadow colour.
    const auto colours = shadow_colours(image, render(nullptr));
    ASSERT_EQ(colours.size(), 1u);
    const auto [r, g, b] = colours.begin()->first;
    EXPECT_TRUE(near(Rgb{r, g, b}, darkened(kFloor, 1.0f - s.alpha), 2)) << Rgb{r, g, b};
}

TEST_F(TechnicalShadowsTest, PenumbraGivesADarkerUmbraInsideALighterFringe) {
    upload_cubes({{{0, 0, 0}, {16, 16, 16}}}, 16.0f);
    ShadowSettings s;
    s.penumbra_offset = 5.0f;  // fringe and middle both a few pixels wide from here
    const std::vector<Rgb> image = render(&s);
    gl_->dump_if_requested("technical_shadow_penumbra");
    const FloorCheck check = check_floor(image, s);
    EXPECT_EQ(check.wrong, 0) << check.first_wrong << " expected " << check.first_expected;
    EXPECT_GT(check.pixels_by_passes[1], 20);  // the fringe: one penumbra pass
    EXPECT_GT(check.pixels_by_passes[3], 20);  // the middle: umbra and both penumbras
    const Rgb fringe = darkened(kFloor, 1.0f - s.penumbra_alpha);
    const Rgb middle =
        darkened(kFloor, (1.0f - s.alpha) * (1.0f - s.penumbra_alpha) * (1.0f - s.penumbra_alpha));
    EXPECT_LT(brightness(middle) + 150, brightness(fringe));
    EXPECT_LT(brightness(fringe) + 50, brightness(kFloor));
}

TEST_F(TechnicalShadowsTest, HardShadowHasExactlyOneLevelPenumbraSeveral) {
    upload_cubes({{{0, 0, 0}, {16, 16, 16}}}, 16.0f);
    const std::vector<Rgb> unshadowed = render(nullptr);
    const ShadowSettings hard = hard_shadows();
    EXPECT_EQ(shadow_colours(render(&hard), unshadowed).size(), 1u);
    const ShadowSettings soft;
    EXPECT_GE(shadow_colours(render(&soft), unshadowed).size(), 2u);
}

TEST_F(TechnicalShadowsTest, ShadowsNeverChangeTheModelsOwnPixels) {
    upload_cubes({{{0, 0, 0}, {16, 16, 16}}}, 16.0f);
    const ShadowSettings s;
    // Where the shadow alone lands, and where the model is: they must overlap for this to test
    // anything (the model hides part of its shadow from this camera).
    const std::vector<Rgb> floor_only = render(nullptr, false);
    const std::vector<Rgb> shadow_only = render(&s, false);
    const std::vector<Rgb> model = render(nullptr);
    const std::vector<Rgb> both = render(&s);
    int hidden_shadow = 0, model_pixels = 0, model_changed = 0;
    for (size_t i = 0; i < both.size(); ++i) {
        const bool is_model = model[i] != floor_only[i];
        const bool under_shadow = shadow_only[i] != floor_only[i];
        model_pixels += is_model;
        hidden_shadow += is_model && under_shadow;
        model_changed += is_model && both[i] != model[i];
    }
    EXPECT_GT(model_pixels, 200);
    EXPECT_GT(hidden_shadow, 30);
    EXPECT_EQ(model_changed, 0);
}

// The stencil is not cleared every frame (each frame marks with values of its own, cleared when
// they run out): frame after frame, across those clears, the shadow is the same.
TEST_F(TechnicalShadowsTest, ShadowsStayTheSameFrameAfterFrame) {
    upload_cubes({{{0, 0, 0}, {16, 16, 16}}}, 16.0f);
    const ShadowSettings s;
    const std::vector<Rgb> expected = render(&s);
    int differing_frames = 0;
    for (int frame = 0; frame < 200; ++frame) {
        if (render(&s) != expected) ++differing_frames;
    }
    EXPECT_EQ(differing_frames, 0);
}

// Two casters whose shadows overlap: like two shadows of one light, the overlap is as dark as
// either shadow alone, and both shadows are drawn.
TEST_F(TechnicalShadowsTest, ShadowsOfTwoCastersMergeWhereTheyOverlap) {
    upload_cubes({{{0, 0, 0}, {16, 16, 16}}}, 16.0f);
    const ShadowSettings hard = hard_shadows();
    const std::vector<Rgb> unshadowed = render(nullptr, false);
    const std::vector<Rgb> one = render(&hard, false);
    nqr_entity second = entity_;
    second.number = 2;
    second.origin[1] += 8.0f;  // half a cube aside: the shadows overlap by half
    second.model_matrix[13] += 8.0f;
    draw_floor();
    shadows_.begin_frame();
    add_shadow(entity_, hard);
    add_shadow(second, hard);
    shadows_.draw(hard);
    const std::vector<Rgb> two = gl_->pixels();
    const auto one_colours = shadow_colours(one, unshadowed);
    const auto two_colours = shadow_colours(two, unshadowed);
    ASSERT_EQ(one_colours.size(), 1u);
    ASSERT_EQ(two_colours.size(), 1u);
    EXPECT_EQ(two_colours.begin()->first, one_colours.begin()->first);         // as dark as one
    EXPECT_GT(two_colours.begin()->second, one_colours.begin()->second + 20);  // more floor
}

TEST_F(TechnicalShadowsTest, RestoresTheClassicStateWithStencilOff) {
    upload_cubes({{{0, 0, 0}, {16, 16, 16}}}, 16.0f);
    const ShadowSettings s;
    draw_floor();
    shadows_.begin_frame();
    draw_shadow(s);
    EXPECT_FALSE(glIsEnabled(GL_STENCIL_TEST));
    EXPECT_FALSE(glIsEnabled(GL_BLEND));
    EXPECT_FALSE(glIsEnabled(GL_POLYGON_OFFSET_FILL));
    EXPECT_FALSE(glIsEnabled(GL_CULL_FACE));
    EXPECT_TRUE(glIsEnabled(GL_DEPTH_TEST));
    GLboolean mask[4] = {};
    glGetBooleani_v(GL_COLOR_WRITEMASK, 1, mask);
    EXPECT_TRUE(mask[0] && mask[1] && mask[2] && mask[3]);
    glGetBooleanv(GL_DEPTH_WRITEMASK, mask);
    EXPECT_TRUE(mask[0]);
    GLint value = -1;
    glGetIntegerv(GL_CURRENT_PROGRAM, &value);
    EXPECT_EQ(value, 0);
    glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &value);
    EXPECT_EQ(value, 0);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

}  // namespace
}  // namespace nq::npr::test

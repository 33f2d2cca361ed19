// The technical style's alias-model edges (nprlib/technical/alias_edge_*): true silhouettes and
// creases from adjacency on the GPU, the back-face-line fallback, edge colours (white addition,
// distance fade), constant pixel width and hidden-edge removal, checked on real pixels of
// synthetic models drawn on Mesa llvmpipe.
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <numbers>

#include "abi/frame_view.h"
#include "adjacency/feature_edges.h"
#include "adjacency/model_adjacency.h"
#include "classic/alias_drawer.h"
#include "classic/alias_model_gpu.h"
#include "classic/classic_pass.h"
#include "support/nprlib_test_support.h"
#include "technical/alias_edge_drawer.h"
#include "technical/alias_edge_mesh.h"
#include "technical/alias_pose.h"
#include "technical/skin_tones.h"
#include "technical/technical_settings.h"

namespace nq::npr::test {
namespace {

using technical::AliasEdgeDrawer;
using technical::AliasEdgeMesh;
using technical::BackfaceLines;
using technical::EdgeColorMode;
using technical::EdgeKind;
using technical::EdgeQuery;
using technical::FoundEdge;
using technical::TechnicalSettings;

const Rgb kBackground{0, 0, 0};
const Rgb kSilhouette{0, 255, 0};
const Rgb kRidge{255, 0, 0};
const Rgb kValley{0, 0, 255};
constexpr uint8_t kGrey = 128;  // a skin palette index: (128, 128, 128)

bool is(const Rgb& pixel, const Rgb& colour) {
    return near(pixel, colour, 8);
}

// ------------------------------------------------------------------ synthetic models

// Quads given counter-clockwise seen from outside, stored clockwise as Quake does.
void add_outward_quad(AliasBuilder& b, int a, int c, int d, int e) {
    b.triangles.push_back({1, a, d, c});
    b.triangles.push_back({1, a, e, d});
}

void add_vertex(AliasBuilder& b, glm::ivec3 packed) {
    if (b.poses.empty()) b.poses.emplace_back();
    b.poses[0].push_back({static_cast<uint8_t>(packed.x), static_cast<uint8_t>(packed.y),
                          static_cast<uint8_t>(packed.z)});
    b.st.push_back({0, 4, 4});
}

// The cube [-8, 8]^3 (12 triangles).
void make_cube(AliasBuilder& b, uint8_t skin) {
    b.add_box_pose({0, 0, 0}, {16, 16, 16});
    b.origin = glm::vec3(-8.0f);
    b.skin.assign(64, skin);
}

// An L-shaped step: the profile (x, z) A(0,0) B(16,0) C(16,8) D(8,8) E(8,16) F(0,16) extruded
// along y from 0 to 16, centred on the origin. D's edge is concave, C's and E's convex.
void make_step(AliasBuilder& b, uint8_t skin) {
    const int profile[6][2] = {{0, 0}, {16, 0}, {16, 8}, {8, 8}, {8, 16}, {0, 16}};
    for (int y : {0, 16}) {
        for (const auto& p : profile) add_vertex(b, {p[0], y, p[1]});
    }
    // Cap y = 0 faces -Y: the profile order is counter-clockwise from there; fan from D (3).
    for (int k : {4, 5, 0, 1}) b.triangles.push_back({1, 3, (k + 1) % 6, k});
    // Cap y = 16 faces +Y: the same fan from D (9), wound the other way.
    for (int k : {4, 5, 0, 1}) b.triangles.push_back({1, 9, 6 + k, 6 + (k + 1) % 6});
    for (int i = 0; i < 6; ++i) add_outward_quad(b, i, i + 6, (i + 1) % 6 + 6, (i + 1) % 6);
    b.origin = glm::vec3(-8.0f);
    b.skin.assign(64, skin);
}

// A torus around +Z: major radius 20, tube radius 8, 24 x 12 quads (576 triangles).
void make_torus(AliasBuilder& b, uint8_t skin, int around = 24, int tube = 12) {
    constexpr float kScale = 0.25f, kMajor = 20.0f, kMinor = 8.0f, kOffset = 28.0f;
    const float two_pi = 2.0f * std::numbers::pi_v<float>;
    for (int u = 0; u < around; ++u) {
        for (int v = 0; v < tube; ++v) {
            const float theta = two_pi * u / around, phi = two_pi * v / tube;
            const float ring = kMajor + kMinor * std::cos(phi);
            const glm::vec3 p(ring * std::cos(theta), ring * std::sin(theta),
                              kMinor * std::sin(phi));
            add_vertex(b, glm::ivec3(glm::round((p + kOffset) / kScale)));
        }
    }
    auto at = [&](int u, int v) { return (u % around) * tube + v % tube; };
    for (int u = 0; u < around; ++u) {
        for (int v = 0; v < tube; ++v) {
            add_outward_quad(b, at(u, v), at(u + 1, v), at(u + 1, v + 1), at(u, v + 1));
        }
    }
    b.scale = glm::vec3(kScale);
    b.origin = glm::vec3(-kOffset);
    b.skin.assign(64, skin);
}

// The cube with, hidden inside it, three triangles sharing one edge: a non-manifold part that
// makes the adjacency verdict fail while the picture stays a convex cube.
void make_broken_cube(AliasBuilder& b, uint8_t skin) {
    make_cube(b, skin);
    for (glm::ivec3 p : {glm::ivec3(8, 8, 3), glm::ivec3(8, 8, 13), glm::ivec3(3, 8, 8),
                         glm::ivec3(13, 8, 8), glm::ivec3(8, 13, 8)}) {
        add_vertex(b, p);
    }
    for (int apex : {10, 11, 12}) b.triangles.push_back({1, 8, apex, 9});
}

// The cube with a skin seam down its edge x = y = -8: the -Y face uses copies (8, 9) of that
// edge's two vertices (0, 4), as a file does where the skin is cut.
void make_seamed_cube(AliasBuilder& b, uint8_t skin) {
    make_cube(b, skin);
    add_vertex(b, {0, 0, 0});
    add_vertex(b, {0, 0, 16});
    for (auto& t : b.triangles) {
        bool minus_y = true;
        for (int k = 1; k < 4; ++k) minus_y = minus_y && b.poses[0][t[k]][1] == 0;
        if (!minus_y) continue;
        for (int k = 1; k < 4; ++k) {
            if (t[k] == 0) t[k] = 8;
            if (t[k] == 4) t[k] = 9;
        }
    }
}

// A thin wall across the x axis, 120 units square.
void make_wall(AliasBuilder& b, uint8_t skin) {
    b.add_box_pose({0, 0, 0}, {2, 120, 120});
    b.origin = {-1.0f, -60.0f, -60.0f};
    b.skin.assign(64, skin);
}

// ------------------------------------------------------------------ cameras and images

// A camera at `eye` looking at `target`.
nqr_camera look_at(glm::vec3 eye, glm::vec3 target) {
    const glm::vec3 d = glm::normalize(target - eye);
    const float pitch = -glm::degrees(std::asin(d.z));
    const float yaw = glm::degrees(std::atan2(d.y, d.x));
    return make_camera(eye, {pitch, yaw, 0.0f});
}

struct Image {
    std::vector<Rgb> pixels;
    const Rgb& at(int x, int y) const { return pixels[y * kSize + x]; }
    bool inside(int x, int y) const { return x >= 0 && y >= 0 && x < kSize && y < kSize; }
    // Whether some pixel within `radius` (Chebyshev) of (x, y) satisfies `test`.
    bool any_near(int x, int y, int radius, const std::function<bool(const Rgb&)>& test) const {
        for (int dy = -radius; dy <= radius; ++dy) {
            for (int dx = -radius; dx <= radius; ++dx) {
                if (inside(x + dx, y + dy) && test(at(x + dx, y + dy))) return true;
            }
        }
        return false;
    }
    int count(const Rgb& colour) const {
        return static_cast<int>(std::count_if(pixels.begin(), pixels.end(),
                                              [&](const Rgb& p) { return is(p, colour); }));
    }
};

// Pixels of a model (not background) with a background 4-neighbour.
std::vector<bool> outline_of(const Image& reference) {
    std::vector<bool> outline(kSize * kSize, false);
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            if (is(reference.at(x, y), kBackground)) continue;
            const int n[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
            for (const auto& d : n) {
                const int nx = x + d[0], ny = y + d[1];
                if (reference.inside(nx, ny) && is(reference.at(nx, ny), kBackground)) {
                    outline[y * kSize + x] = true;
                }
            }
        }
    }
    return outline;
}

// Chebyshev distance from (x, y) to the nearest marked pixel, capped at `cap`.
int distance_to(const std::vector<bool>& marks, int x, int y, int cap) {
    for (int r = 0; r < cap; ++r) {
        for (int dy = -r; dy <= r; ++dy) {
            for (int dx = -r; dx <= r; ++dx) {
                const int px = x + dx, py = y + dy;
                if (px >= 0 && py >= 0 && px < kSize && py < kSize && marks[py * kSize + px]) {
                    return r;
                }
            }
        }
    }
    return cap;
}

// Distance of point p from segment a-b (window pixels).
float segment_distance(glm::vec2 p, glm::vec2 a, glm::vec2 b) {
    const glm::vec2 ab = b - a;
    const float t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0f, 1.0f);
    return glm::length(p - (a + t * ab));
}

// Gooch 98 with splash-back, written out independently of the shader: the lit side warm,
//   I = (1 + n.l)/2 k_warm + (1 - n.l)/2 k_cool,  k_cool = (0,0,b) + alpha kd,
//   k_warm = (y,y,0) + beta kd,  then I *= (alpha_s |n.l| + 1 - alpha_s)^p.
Rgb expected_gooch(const technical::ShadingSettings& s, Rgb skin, float n_dot_l) {
    const glm::vec3 kd = glm::vec3(skin.r, skin.g, skin.b) / 255.0f;
    const glm::vec3 cool = glm::vec3(0.0f, 0.0f, s.blue) + s.alpha * kd;
    const glm::vec3 warm = glm::vec3(s.yellow, s.yellow, 0.0f) + s.beta * kd;
    glm::vec3 c = (1.0f + n_dot_l) * 0.5f * warm + (1.0f - n_dot_l) * 0.5f * cool;
    c *= std::pow(s.splashback_alpha * std::abs(n_dot_l) + 1.0f - s.splashback_alpha,
                  s.splashback_p);
    c = glm::clamp(c, 0.0f, 1.0f) * 255.0f;
    return {static_cast<int>(std::lround(c.r)), static_cast<int>(std::lround(c.g)),
            static_cast<int>(std::lround(c.b))};
}

// Edge settings with one plain colour per kind and quads wide enough to probe at 128 lines
// (12 pixels at 480 lines = 3.2 here).
TechnicalSettings plain_settings() {
    TechnicalSettings s;
    s.edges.color_mode = EdgeColorMode::base;
    s.edges.distance_fade = false;
    s.edges.silhouette_color = glm::vec3(0.0f, 1.0f, 0.0f);
    s.edges.ridge_color = glm::vec3(1.0f, 0.0f, 0.0f);
    s.edges.valley_color = glm::vec3(0.0f, 0.0f, 1.0f);
    s.edges.silhouette_width = s.edges.ridge_width = s.edges.valley_width = 12.0f;
    s.edges.backface_width = 12.0f;
    return s;
}

// ------------------------------------------------------------------ fixture

struct TestModel {
    AliasBuilder builder;
    std::unique_ptr<classic::AliasModelGpu> faces;
    std::unique_ptr<AliasEdgeMesh> edges;
};

// What one draw call puts on screen: an entity, and whether its edges are drawn.
struct Drawn {
    TestModel* model;
    nqr_entity* entity;
    bool edges = true;
};

class TechnicalEdgesTest : public GlSuiteTest<TechnicalEdgesTest> {
  protected:
    void SetUp() override {
        GlSuiteTest::SetUp();
        if (HasFatalFailure()) return;
        std::string error;
        ASSERT_TRUE(faces_.init(&tracker_, engine_.palette.data(), error)) << error;
        ASSERT_TRUE(edges_.init(&tracker_, error)) << error;
    }

    void TearDown() override {
        models_.clear();
        faces_.reset();
        edges_.reset();
        EXPECT_EQ(tracker_.total_live(), 0);
    }

    TestModel& add_model(const std::function<void(AliasBuilder&)>& make) {
        auto model = std::make_unique<TestModel>();
        make(model->builder);
        const nqr_alias_model& source = *model->builder.build();
        std::string error;
        model->faces =
            classic::AliasModelGpu::create(&tracker_, source, engine_.palette.data(), error);
        EXPECT_NE(model->faces, nullptr) << error;
        model->edges = AliasEdgeMesh::create(source, error);
        EXPECT_NE(model->edges, nullptr) << error;
        models_.push_back(std::move(model));
        return *models_.back();
    }

    // Faces of every item (fullbright classic drawer: the skin colour), then the edges.
    Image draw(const nqr_camera& camera, std::initializer_list<Drawn> items,
               const TechnicalSettings& settings) {
        gl_->clear(kBackground);
        const nqr_frame* frame = frame_.build(camera, 0);
        npr::FrameView view;
        EXPECT_TRUE(npr::read_frame_view(frame, view));
        technical::EdgeFrameUniforms uniforms;
        uniforms.projection = glm::make_mat4(camera.projection);
        uniforms.viewport = glm::vec2(kSize, kSize);
        uniforms.z_near = camera.z_near;
        classic::begin_classic_pass();
        for (const Drawn& item : items) {
            place_eye(*item.entity, camera);
            faces_.draw_entity(*frame, view, *item.entity, *item.model->faces);
        }
        for (const Drawn& item : items) {
            if (!item.edges) continue;
            edges_.draw_entity(view, uniforms, *item.entity, *item.model->faces, *item.model->edges,
                               skin_of(*item.model->faces, *item.entity), settings);
        }
        classic::end_classic_pass();
        EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
        return {gl_->pixels()};
    }

    technical::SkinSample skin_of(const classic::AliasModelGpu& faces,
                                  const nqr_entity& entity) const {
        return technical::sample_skin(faces.model(), faces.skin_pixels(0, 0), entity,
                                      engine_.palette.data());
    }

    static void place_eye(nqr_entity& entity, const nqr_camera& camera) {
        const glm::mat4 to_model = glm::inverse(glm::make_mat4(entity.model_matrix));
        const glm::vec3 eye = glm::vec3(to_model * glm::vec4(glm::make_vec3(camera.origin), 1.0f));
        std::copy_n(glm::value_ptr(eye), 3, entity.eye_model);
    }

    static nqr_entity fullbright_entity(nqr_model_id id, glm::mat4 matrix = glm::mat4(1.0f)) {
        nqr_entity entity = make_entity(id, matrix);
        entity.flags = NQR_ENTITY_FULLBRIGHT;
        return entity;
    }

    static Rgb probe(const Image& image, const nqr_camera& camera, glm::vec3 world) {
        const glm::vec2 p = project(camera, world);
        return image.at(static_cast<int>(p.x), static_cast<int>(p.y));
    }

    Rgb colour(int index) const { return palette_colour(engine_.palette, index); }

    TestEngine engine_;
    gl::ObjectTracker tracker_;
    classic::AliasDrawer faces_;
    AliasEdgeDrawer edges_;
    TestFrame frame_;
    std::vector<std::unique_ptr<TestModel>> models_;
};

// From above the (-X, -Y, +Z) corner: -X, -Y and +Z face the eye; their three shared edges are
// creases between front faces, the hexagon around them the silhouette.
nqr_camera corner_camera() {
    return look_at({-24.0f, -18.0f, 21.6f}, glm::vec3(0.0f));
}

// ------------------------------------------------------------------ the mesh

TEST_F(TechnicalEdgesTest, MeshHoldsAdjacencyAndTrianglesAndTheVerdict) {
    TestModel& cube = add_model([](AliasBuilder& b) { make_cube(b, kGrey); });
    EXPECT_TRUE(cube.edges->clean());
    EXPECT_EQ(cube.edges->edge_count(), 18u);  // 12 box edges, 6 face diagonals
    EXPECT_EQ(cube.edges->triangles().size(), 12u);
    EXPECT_EQ(cube.edges->vertex_count(), cube.builder.build()->num_vertices);
    EXPECT_EQ(cube.edges->stats().mesh.edges, 18u);
    const std::string line = cube.edges->verdict_line("progs/cube.mdl");
    EXPECT_NE(line.find("progs/cube.mdl"), std::string::npos) << line;
    EXPECT_NE(line.find("true silhouettes"), std::string::npos) << line;

    TestModel& broken = add_model([](AliasBuilder& b) { make_broken_cube(b, kGrey); });
    EXPECT_FALSE(broken.edges->clean()) << broken.edges->verdict_line("broken");
    EXPECT_EQ(broken.edges->triangles().size(), 15u);
}

// The edges of `model`'s first pose seen from `eye` (model space), counted by kind.
std::array<int, 4> found_kinds(TestModel& model, glm::vec3 eye, const EdgeQuery& query) {
    const nqr_alias_model& source = *model.builder.build();
    nqr_entity entity = make_entity(1);
    std::vector<glm::vec3> pose(source.num_vertices);
    technical::blend_alias_pose(source, entity, pose.data());
    std::vector<FoundEdge> found;
    model.edges->find_edges(pose.data(), eye, query, found);
    std::array<int, 4> kinds{};
    for (const FoundEdge& e : found) ++kinds[static_cast<int>(e.kind)];
    return kinds;
}

// The cube (model space -8..8) seen from a corner direction shows three faces. Its 12 box
// edges: 3 between two visible faces (creases, convex: ridges), 6 on the outline
// (silhouettes), 3 between hidden faces; the 6 face diagonals are flat. Counted independently.
TEST_F(TechnicalEdgesTest, FoundEdgesAreTheOutlineAndTheVisibleCreases) {
    TestModel& cube = add_model([](AliasBuilder& b) { make_cube(b, kGrey); });
    const glm::vec3 corner_eye(100.0f, 70.0f, 40.0f);
    EdgeQuery query;
    query.silhouettes = query.creases = true;
    query.cos_crease = 0.5f;  // 60 degrees
    EXPECT_EQ(found_kinds(cube, corner_eye, query), (std::array<int, 4>{6, 3, 0, 0}));
    query.creases = false;
    EXPECT_EQ(found_kinds(cube, corner_eye, query), (std::array<int, 4>{6, 0, 0, 0}));
    // Above 90 degrees no box edge is a crease: the outline alone.
    query.creases = true;
    query.cos_crease = -0.2f;
    EXPECT_EQ(found_kinds(cube, corner_eye, query), (std::array<int, 4>{6, 0, 0, 0}));
    // Straight at one face: its 4 edges are the outline (the side faces are edge-on, not seen),
    // nothing else faces the eye.
    query.cos_crease = 0.5f;
    EXPECT_EQ(found_kinds(cube, {200.0f, 0.0f, 0.0f}, query), (std::array<int, 4>{4, 0, 0, 0}));
    // Silhouettes off: an outline edge turns by 90 degrees, so it is a crease then.
    query.silhouettes = false;
    EXPECT_EQ(found_kinds(cube, corner_eye, query)[0], 0);
    EXPECT_EQ(found_kinds(cube, corner_eye, query)[1], 9);
}

// Back-face lines: the three hidden faces' six triangles have 18 sides; the 3 hidden box edges
// and the 3 hidden diagonals lie between two hidden triangles (behind the model): left out.
// The 6 outline edges remain, once each.
TEST_F(TechnicalEdgesTest, BackfaceLinesKeepTheEdgesOfHiddenTrianglesThatCanShow) {
    TestModel& cube = add_model([](AliasBuilder& b) { make_cube(b, kGrey); });
    EdgeQuery query;
    query.backface_lines = true;
    EXPECT_EQ(found_kinds(cube, {100.0f, 70.0f, 40.0f}, query), (std::array<int, 4>{0, 0, 0, 6}));
    // The broken cube's fin: three triangles on one side have no twins, so those of them that
    // face away keep all their sides.
    TestModel& broken = add_model([](AliasBuilder& b) { make_broken_cube(b, kGrey); });
    EXPECT_GT(found_kinds(broken, {100.0f, 70.0f, 40.0f}, query)[3], 6);
    // A seam between two faces that both face away hides the edge as well as a shared vertex
    // pair does: the same six rim edges as the plain cube.
    TestModel& seamed = add_model([](AliasBuilder& b) { make_seamed_cube(b, kGrey); });
    EXPECT_EQ(found_kinds(seamed, {100.0f, 70.0f, 40.0f}, query), (std::array<int, 4>{0, 0, 0, 6}));
}

TEST_F(TechnicalEdgesTest, UnreadableModelIsRefusedWithAReason) {
    nqr_alias_model empty{};
    empty.size = sizeof empty;
    std::string error;
    EXPECT_EQ(AliasEdgeMesh::create(empty, error), nullptr);
    EXPECT_FALSE(error.empty());
}

// ------------------------------------------------------------------ creases

TEST_F(TechnicalEdgesTest, CubeCreasesAreRidgesAndStepsInnerEdgeIsAValley) {
    TestModel& cube = add_model([](AliasBuilder& b) { make_cube(b, kGrey); });
    nqr_entity entity = fullbright_entity(1);
    const nqr_camera camera = corner_camera();
    const Image image = draw(camera, {{&cube, &entity}}, plain_settings());
    gl_->dump_if_requested("technical_edges_cube");

    // The three creases at the near corner (-8, -8, 8): ridges at their midpoints, and every
    // ridge pixel lies along one of them.
    const glm::vec3 corner(-8.0f, -8.0f, 8.0f);
    const glm::vec3 ends[3] = {{-8, -8, -8}, {-8, 8, 8}, {8, -8, 8}};
    for (const glm::vec3& end : ends) {
        EXPECT_EQ(probe(image, camera, (corner + end) * 0.5f), kRidge) << end.x << end.y << end.z;
    }
    int ridge_pixels = 0, stray = 0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            if (!is(image.at(x, y), kRidge)) continue;
            ++ridge_pixels;
            float nearest = 1e9f;
            for (const glm::vec3& end : ends) {
                nearest = std::min(nearest,
                                   segment_distance({x + 0.5f, y + 0.5f}, project(camera, corner),
                                                    project(camera, end)));
            }
            stray += nearest > 3.0f;
        }
    }
    EXPECT_GT(ridge_pixels, 60);
    EXPECT_EQ(stray, 0);
    EXPECT_EQ(image.count(kValley), 0);
    // The silhouette hexagon: the top face's far edges, the side faces' far vertical edges and
    // the bottom's near edges.
    for (glm::vec3 p : {glm::vec3(8, 0, 8), glm::vec3(0, 8, 8), glm::vec3(-8, 8, 0),
                        glm::vec3(8, -8, 0), glm::vec3(-8, 0, -8), glm::vec3(0, -8, -8)}) {
        EXPECT_EQ(probe(image, camera, p), kSilhouette) << p.x << " " << p.y << " " << p.z;
    }

    TestModel& step = add_model([](AliasBuilder& b) { make_step(b, kGrey); });
    EXPECT_TRUE(step.edges->clean()) << step.edges->verdict_line("step");
    nqr_entity step_entity = fullbright_entity(2);
    const nqr_camera step_camera = look_at({30.0f, -15.0f, 27.0f}, glm::vec3(0.0f));
    const Image step_image = draw(step_camera, {{&step, &step_entity}}, plain_settings());
    gl_->dump_if_requested("technical_edges_step");
    EXPECT_EQ(probe(step_image, step_camera, {0, 0, 0}), kValley);  // D: the inner corner
    EXPECT_EQ(probe(step_image, step_camera, {8, 0, 0}), kRidge);   // C: the lower step's lip
    EXPECT_EQ(probe(step_image, step_camera, {0, 0, 8}), kRidge);   // E: the upper step's lip
    EXPECT_GT(step_image.count(kValley), 40);
}

// The technical style draws the creases adjacency::classify_edge finds, with the threshold the
// adjacency's crease_cosine gives: a change of the threshold there changes the picture. Below 90
// degrees the corner's three box edges are ridges (a ridge pixel at each one's midpoint), above
// it there is no crease on the cube at all, in the adjacency's answer and on screen.
TEST_F(TechnicalEdgesTest, TheCreasesOnScreenAreTheAdjacencyTestsCreases) {
    TestModel& cube = add_model([](AliasBuilder& b) { make_cube(b, kGrey); });
    const nqr_alias_model& source = *cube.builder.build();
    const adjacency::ModelAdjacency adj = adjacency::recover_adjacency(source);
    nqr_entity entity = fullbright_entity(1);
    const nqr_camera camera = corner_camera();
    place_eye(entity, camera);
    const glm::vec3 eye = glm::make_vec3(entity.eye_model);
    std::vector<glm::vec3> pose(source.num_vertices);
    technical::blend_alias_pose(source, entity, pose.data());
    for (const float degrees : {60.0f, 100.0f}) {
        adjacency::FeatureTest test;
        test.cos_crease = adjacency::crease_cosine(degrees);
        std::vector<adjacency::ClassifiedEdge> found;
        adjacency::find_feature_edges(adj.edges.records, pose.data(), eye, test, found);
        std::vector<glm::vec3> ridge_midpoints;
        for (const adjacency::ClassifiedEdge& e : found) {
            if (e.kind != adjacency::FeatureEdge::ridge) continue;
            const adjacency::EdgeRecord& r = adj.edges.records[e.edge];
            ridge_midpoints.push_back((pose[r.v0] + pose[r.v1]) * 0.5f);
        }
        EXPECT_EQ(ridge_midpoints.size(), degrees < 90.0f ? 3u : 0u) << degrees;

        TechnicalSettings settings = plain_settings();
        settings.edges.crease_angle_degrees = degrees;
        const Image image = draw(camera, {{&cube, &entity}}, settings);
        for (const glm::vec3& midpoint : ridge_midpoints) {
            EXPECT_EQ(probe(image, camera, midpoint), kRidge) << degrees;
        }
        if (ridge_midpoints.empty()) {
            EXPECT_EQ(image.count(kRidge), 0) << degrees;
        } else {
            EXPECT_GT(image.count(kRidge), 60) << degrees;
        }
    }
}

TEST_F(TechnicalEdgesTest, DrawingLeavesTheDocumentedGlState) {
    TestModel& cube = add_model([](AliasBuilder& b) { make_cube(b, kGrey); });
    nqr_entity entity = fullbright_entity(1);
    const nqr_camera camera = corner_camera();
    place_eye(entity, camera);
    npr::FrameView view;
    ASSERT_TRUE(npr::read_frame_view(frame_.build(camera, 0), view));
    const technical::SkinSample skin = skin_of(*cube.faces, entity);
    TechnicalSettings settings = plain_settings();
    for (BackfaceLines policy : {BackfaceLines::never, BackfaceLines::always}) {
        settings.edges.backface_lines = policy;
        classic::begin_classic_pass();
        edges_.draw_entity(view, {}, entity, *cube.faces, *cube.edges, skin, settings);
        GLint value = -1;
        glGetIntegerv(GL_CURRENT_PROGRAM, &value);
        EXPECT_EQ(value, 0);
        glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &value);
        EXPECT_EQ(value, 0);
        glGetIntegerv(GL_ACTIVE_TEXTURE, &value);
        EXPECT_EQ(value, GL_TEXTURE0);
        glGetIntegerv(GL_DEPTH_FUNC, &value);
        EXPECT_EQ(value, GL_LEQUAL);
        GLboolean mask = GL_FALSE;
        glGetBooleanv(GL_DEPTH_WRITEMASK, &mask);
        EXPECT_EQ(mask, GL_TRUE);
        EXPECT_TRUE(glIsEnabled(GL_DEPTH_TEST));
        EXPECT_FALSE(glIsEnabled(GL_BLEND));
        EXPECT_FALSE(glIsEnabled(GL_CULL_FACE));
        EXPECT_FALSE(glIsEnabled(GL_STENCIL_TEST));
        EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    }
}

// ------------------------------------------------------------------ silhouettes

// Silhouettes only, compared with the flat-colour outline of the same model.
void expect_silhouettes_follow_outline(const Image& reference, const Image& edges,
                                       const char* what) {
    const std::vector<bool> outline = outline_of(reference);
    std::vector<bool> edge_marks(kSize * kSize);
    for (int i = 0; i < kSize * kSize; ++i) edge_marks[i] = is(edges.pixels[i], kSilhouette);
    int outline_pixels = 0, covered = 0, edge_pixels = 0, far_edges = 0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            if (outline[y * kSize + x]) {
                ++outline_pixels;
                covered += distance_to(edge_marks, x, y, 2) <= 1;
            }
            if (edge_marks[y * kSize + x]) {
                ++edge_pixels;
                far_edges += distance_to(outline, x, y, 3) > 2;
            }
        }
    }
    ASSERT_GT(outline_pixels, 100) << what;
    EXPECT_GE(covered, 0.95 * outline_pixels) << what << ": " << covered << "/" << outline_pixels;
    EXPECT_LT(far_edges, 0.10 * edge_pixels) << what << ": " << far_edges << "/" << edge_pixels;
}

TEST_F(TechnicalEdgesTest, SilhouettesFollowTheOutline) {
    TestModel& cube = add_model([](AliasBuilder& b) { make_cube(b, kGrey); });
    TestModel& torus = add_model([](AliasBuilder& b) { make_torus(b, kGrey); });
    EXPECT_TRUE(torus.edges->clean()) << torus.edges->verdict_line("torus");
    TechnicalSettings settings = plain_settings();
    settings.edges.creases = false;
    settings.edges.silhouette_width = 7.5f;  // 2 pixels: the outline within 1 of the edge

    nqr_entity cube_entity = fullbright_entity(1);
    const nqr_camera camera = corner_camera();
    expect_silhouettes_follow_outline(draw(camera, {{&cube, &cube_entity, false}}, settings),
                                      draw(camera, {{&cube, &cube_entity}}, settings), "cube");

    // The torus tilted and moved by its entity matrix: facing uses the eye in model space.
    const glm::mat4 placed = glm::rotate(glm::translate(glm::mat4(1.0f), {10.0f, 5.0f, -4.0f}),
                                         glm::radians(50.0f), glm::normalize(glm::vec3(1, 2, 0)));
    nqr_entity torus_entity = fullbright_entity(2, placed);
    const nqr_camera torus_camera = look_at({-70.0f, 0.0f, 0.0f}, {10.0f, 5.0f, -4.0f});
    const Image reference = draw(torus_camera, {{&torus, &torus_entity, false}}, settings);
    const Image edges = draw(torus_camera, {{&torus, &torus_entity}}, settings);
    gl_->dump_if_requested("technical_edges_torus");
    expect_silhouettes_follow_outline(reference, edges, "torus");
}

TEST_F(TechnicalEdgesTest, EdgesFollowTheBlendedPose) {
    TestModel& cube = add_model([](AliasBuilder& b) {
        make_cube(b, kGrey);
        b.add_box_pose({0, 40, 0}, {16, 56, 16});  // pose 1: 40 units along +Y
    });
    nqr_entity entity = fullbright_entity(1);
    entity.pose0 = 0;
    entity.pose1 = 1;
    entity.lerp = 0.5f;  // the cube at y = 20
    const nqr_camera camera = corner_camera();
    const Image image = draw(camera, {{&cube, &entity}}, plain_settings());
    EXPECT_EQ(probe(image, camera, {-8, 12, 0}), kRidge);       // the near vertical crease
    EXPECT_EQ(probe(image, camera, {8, 20, 8}), kSilhouette);   // the top's far edge
    EXPECT_EQ(probe(image, camera, {-8, -8, 0}), kBackground);  // where pose 0 had a crease
}

// ------------------------------------------------------------------ colours

class TechnicalEdgeColourTest : public TechnicalEdgesTest {
  protected:
    // The cube lit from above, silhouettes only; probes the top face's far silhouette edge,
    // whose corners (8, +-8, 8) both have n.l = 1/sqrt(3).
    Rgb far_top_edge(const TechnicalSettings& settings) {
        if (!cube_) cube_ = &add_model([](AliasBuilder& b) { make_cube(b, colour::kOrange); });
        nqr_entity entity = make_entity(1);  // light straight down from +Z (make_entity)
        const nqr_camera camera = corner_camera();
        return probe(draw(camera, {{cube_, &entity}}, settings), camera, {8, 0, 8});
    }

    TechnicalSettings silhouette_settings() {
        TechnicalSettings s = plain_settings();
        s.edges.creases = false;
        return s;
    }

    Rgb shaded() const {
        return expected_gooch(technical::ShadingSettings{}, colour(colour::kOrange),
                              1.0f / std::sqrt(3.0f));
    }

    TestModel* cube_ = nullptr;
};

TEST_F(TechnicalEdgeColourTest, WhiteAdditionGoesFromShadedToWhite) {
    TechnicalSettings settings = silhouette_settings();
    settings.edges.color_mode = EdgeColorMode::white_all;
    settings.edges.white_w = 1.0f;
    EXPECT_TRUE(near(far_top_edge(settings), Rgb{255, 255, 255}, 2)) << far_top_edge(settings);
    settings.edges.white_w = 0.0f;
    const Rgb expected = shaded();
    EXPECT_TRUE(near(far_top_edge(settings), expected, 3))
        << far_top_edge(settings) << " expected " << expected;
    settings.edges.white_w = 0.25f;
    const Rgb quarter{std::min(255, expected.r + 64), std::min(255, expected.g + 64),
                      std::min(255, expected.b + 64)};
    EXPECT_TRUE(near(far_top_edge(settings), quarter, 3)) << far_top_edge(settings);
}

TEST_F(TechnicalEdgeColourTest, DistanceFadeTurnsFarEdgesIntoTheModelColour) {
    TechnicalSettings settings = silhouette_settings();
    settings.edges.distance_fade = true;
    settings.edges.fade_distance = 5.0f;  // the cube is ~30 units away
    EXPECT_TRUE(near(far_top_edge(settings), shaded(), 3))
        << far_top_edge(settings) << " expected " << shaded();
    settings.edges.fade_distance = 1.0e6f;
    EXPECT_TRUE(near(far_top_edge(settings), kSilhouette, 2)) << far_top_edge(settings);
}

// ------------------------------------------------------------------ width

TEST_F(TechnicalEdgesTest, EdgeWidthInPixelsIsTheSameNearAndFar) {
    TestModel& cube = add_model([](AliasBuilder& b) { make_cube(b, kGrey); });
    nqr_entity entity = fullbright_entity(1);
    TechnicalSettings settings = plain_settings();
    settings.edges.silhouettes = false;
    settings.edges.ridge_width = 30.0f;
    const int expected = static_cast<int>(std::lround(30.0 * kSize / 480.0));  // 8 pixels
    // The vertical crease between -X and -Y, seen edge-on from its diagonal: a vertical line.
    for (float away : {24.0f, 60.0f}) {
        const nqr_camera camera = look_at({-away, -away, 0.0f}, glm::vec3(0.0f));
        const Image image = draw(camera, {{&cube, &entity}}, settings);
        const glm::vec2 centre = project(camera, {-8.0f, -8.0f, 0.0f});
        const int y = static_cast<int>(centre.y), x0 = static_cast<int>(centre.x);
        ASSERT_EQ(image.at(x0, y), kRidge) << away;
        int left = x0, right = x0;
        while (left > 0 && is(image.at(left - 1, y), kRidge)) --left;
        while (right < kSize - 1 && is(image.at(right + 1, y), kRidge)) ++right;
        EXPECT_NEAR(right - left + 1, expected, 1) << "eye " << away << " units out";
    }
}

// ------------------------------------------------------------------ back-face lines

struct RingCounts {
    int outer = 0, outer_edge = 0;  // background pixels next to the model, those with edges
    int inner = 0, inner_edge = 0;  // model pixels 2-3 from the background, those with edges
    int deep_edge = 0;              // edge pixels deeper inside the model
};

// Compares an edge image with the model's flat reference around the reference outline.
RingCounts ring_counts(const Image& reference, const Image& edges) {
    std::vector<bool> background(kSize * kSize);
    for (int i = 0; i < kSize * kSize; ++i) background[i] = is(reference.pixels[i], kBackground);
    RingCounts c;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const bool edge = is(edges.at(x, y), kSilhouette);
            if (background[y * kSize + x]) {
                if (!reference.any_near(x, y, 1, [](const Rgb& p) { return !is(p, kBackground); }))
                    continue;
                ++c.outer;
                c.outer_edge += edge;
                continue;
            }
            const int depth = distance_to(background, x, y, 5);
            if (depth == 2 || depth == 3) {
                ++c.inner;
                c.inner_edge += edge;
            } else if (depth > 3) {
                c.deep_edge += edge;
            }
        }
    }
    return c;
}

TEST_F(TechnicalEdgesTest, BackfaceLinesOutlineButStayOffTheFrontFaces) {
    TestModel& cube = add_model([](AliasBuilder& b) { make_cube(b, kGrey); });
    nqr_entity entity = fullbright_entity(1);
    const nqr_camera camera = corner_camera();
    TechnicalSettings settings = plain_settings();
    settings.edges.creases = false;
    settings.edges.silhouette_width = settings.edges.backface_width = 24.0f;  // 6.4 pixels
    const Image reference = draw(camera, {{&cube, &entity, false}}, settings);

    settings.edges.backface_lines = BackfaceLines::always;
    const RingCounts lines = ring_counts(reference, draw(camera, {{&cube, &entity}}, settings));
    gl_->dump_if_requested("technical_edges_backface");
    EXPECT_GE(lines.outer_edge, 0.9 * lines.outer);
    EXPECT_EQ(lines.inner_edge, 0);
    EXPECT_EQ(lines.deep_edge, 0);

    // True silhouettes are pulled toward the eye: their inner half covers the faces.
    settings.edges.backface_lines = BackfaceLines::never;
    const RingCounts silhouettes =
        ring_counts(reference, draw(camera, {{&cube, &entity}}, settings));
    EXPECT_GE(silhouettes.outer_edge, 0.9 * silhouettes.outer);
    EXPECT_GE(silhouettes.inner_edge, 0.5 * silhouettes.inner);
    EXPECT_EQ(silhouettes.deep_edge, 0);
}

TEST_F(TechnicalEdgesTest, UncleanModelsGetBackfaceLinesAndNoCreases) {
    TestModel& broken = add_model([](AliasBuilder& b) { make_broken_cube(b, kGrey); });
    ASSERT_FALSE(broken.edges->clean());
    nqr_entity entity = fullbright_entity(1);
    const nqr_camera camera = corner_camera();
    TechnicalSettings settings = plain_settings();
    settings.edges.silhouette_width = settings.edges.backface_width = 24.0f;
    const Image reference = draw(camera, {{&broken, &entity, false}}, settings);

    settings.edges.backface_lines = BackfaceLines::unclean_models;  // the default
    const Image image = draw(camera, {{&broken, &entity}}, settings);
    const RingCounts lines = ring_counts(reference, image);
    EXPECT_GE(lines.outer_edge, 0.8 * lines.outer);
    EXPECT_EQ(lines.inner_edge, 0);
    EXPECT_EQ(image.count(kRidge), 0);  // creases need trustworthy adjacency

    // Refusing back-face lines draws the adjacency's edges anyway, creases included.
    settings.edges.backface_lines = BackfaceLines::never;
    const Image forced = draw(camera, {{&broken, &entity}}, settings);
    EXPECT_GT(forced.count(kRidge), 60);
}

TEST_F(TechnicalEdgesTest, AlwaysBackfaceLinesKeepCreasesOfCleanModels) {
    TestModel& cube = add_model([](AliasBuilder& b) { make_cube(b, kGrey); });
    nqr_entity entity = fullbright_entity(1);
    const nqr_camera camera = corner_camera();
    TechnicalSettings settings = plain_settings();
    settings.edges.backface_lines = BackfaceLines::always;
    const Image image = draw(camera, {{&cube, &entity}}, settings);
    gl_->dump_if_requested("technical_edges_always");
    EXPECT_EQ(probe(image, camera, {-8, -8, 0}), kRidge);
    EXPECT_GT(image.count(kSilhouette), 100);
}

// ------------------------------------------------------------------ hidden edges

TEST_F(TechnicalEdgesTest, EdgesBehindAnOpaqueObjectStayHidden) {
    TestModel& cube = add_model([](AliasBuilder& b) { make_cube(b, kGrey); });
    TestModel& wall = add_model([](AliasBuilder& b) { make_wall(b, kGrey); });
    nqr_entity cube_entity = fullbright_entity(1);
    nqr_entity wall_entity =
        fullbright_entity(2, glm::translate(glm::mat4(1.0f), {-30.0f, 0.0f, 0.0f}));
    const nqr_camera camera = look_at({-64.0f, -12.0f, 10.0f}, glm::vec3(0.0f));
    TechnicalSettings settings = plain_settings();
    settings.edges.silhouette_width = settings.edges.ridge_width = 24.0f;

    const Image open = draw(camera, {{&cube, &cube_entity}}, settings);
    EXPECT_GT(open.count(kSilhouette), 100);
    EXPECT_GT(open.count(kRidge), 20);
    for (BackfaceLines policy : {BackfaceLines::never, BackfaceLines::always}) {
        settings.edges.backface_lines = policy;
        const Image hidden =
            draw(camera, {{&cube, &cube_entity}, {&wall, &wall_entity, false}}, settings);
        EXPECT_EQ(hidden.count(Rgb{kGrey, kGrey, kGrey}), kSize * kSize);
        EXPECT_EQ(hidden.count(kSilhouette) + hidden.count(kRidge) + hidden.count(kValley), 0);
    }
}

}  // namespace
}  // namespace nq::npr::test

// OcclusionCuller: entities the world hides completely are flagged NQR_ENTITY_OCCLUDED.
//
// Synthetic walls check the rules one at a time (shared edges close a seam only when both faces
// are drawn, unshared seams and outlines are never crossed, depth comes from the face's plane,
// sky and liquids hide nothing). Then both demos are played through SceneBuilder and each
// frame's world and brush entities are drawn by OpenGL (llvmpipe): every alias entity flagged
// occluded, drawn after them, must pass the depth test at no sample at all, every one flagged
// outside the view must land on no sample; and the culler must find most of the models the
// GPU hides.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "app/frame/scene_builder.h"
#include "support/engine_demo_replay.h"
#include "support/nprlib_test_support.h"
#include "render/occlusion_culler.h"
#include "render/view_transform.h"

namespace nq {
namespace {

// ------------------------------------------------------------------ synthetic walls

// Quads facing the eye at the origin, which looks down +x (Quake: x forward, y left, z up).
class Walls {
  public:
    // A quad in the plane x = depth spanning [y0, y1] x [z0, z1], seen from -x. Corners that
    // equal an earlier quad's corners take the same vertex id when `share` is set.
    // With `facing_away` the quad's front looks down +x: the eye sees its back.
    void add(float depth, float y0, float y1, float z0, float z1, bool share = true,
             uint32_t flags = 0, bool facing_away = false) {
        nqr_surface s{};
        s.size = sizeof(nqr_surface);
        s.first_vertex = static_cast<uint32_t>(ids_.size());
        s.num_vertices = 4;
        s.normal[0] = facing_away ? 1.0f : -1.0f;
        s.dist = facing_away ? depth : -depth;
        s.texture = 0;
        s.flags = flags;
        // Counter-clockwise seen from the front (from -x, y grows to the left).
        float corners[4][2] = {{y1, z0}, {y0, z0}, {y0, z1}, {y1, z1}};
        if (facing_away) std::swap(corners[1], corners[3]);
        for (const auto& c : corners) {
            positions_.insert(positions_.end(), {depth, c[0], c[1]});
            ids_.push_back(vertex_id(depth, c[0], c[1], share));
        }
        surfaces_.push_back(s);
    }

    nqr_brush_model model() {
        texture_ = nqr_texture{};
        texture_.size = sizeof(nqr_texture);
        texture_.name = "wall";
        nqr_brush_model m{};
        m.size = sizeof(m);
        m.num_surfaces = static_cast<uint32_t>(surfaces_.size());
        m.surfaces = surfaces_.data();
        m.num_vertices = static_cast<uint32_t>(ids_.size());
        m.positions = positions_.data();
        m.vertex_ids = ids_.data();
        m.num_textures = 1;
        m.textures = &texture_;
        return m;
    }

  private:
    uint32_t vertex_id(float x, float y, float z, bool share) {
        for (size_t i = 0; share && i < points_.size(); ++i) {
            if (points_[i] == glm::vec3(x, y, z)) return static_cast<uint32_t>(i);
        }
        points_.emplace_back(x, y, z);
        return static_cast<uint32_t>(points_.size() - 1);
    }

    std::vector<nqr_surface> surfaces_;
    std::vector<float> positions_;
    std::vector<uint32_t> ids_;
    std::vector<glm::vec3> points_;
    nqr_texture texture_{};
};

nqr_camera eye_at_origin() {
    CameraSetup setup;
    setup.viewport[2] = 160;
    setup.viewport[3] = 120;
    nqr_camera camera;
    fill_camera(setup, camera);
    return camera;
}

// A 16-unit cube centred at (x, y, z).
struct Probe {
    float x, y, z;
};

std::vector<int32_t> add_probes(OcclusionCuller& culler, const std::vector<Probe>& probes) {
    std::vector<int32_t> ids;
    for (const Probe& p : probes) {
        glm::mat4 placement(1.0f);
        placement[3] = glm::vec4(p.x, p.y, p.z, 1.0f);
        ids.push_back(culler.add_box(placement, glm::vec3(-8.0f), glm::vec3(8.0f)));
    }
    return ids;
}

std::vector<bool> verdicts(const OcclusionCuller& culler, const std::vector<int32_t>& ids) {
    std::vector<bool> out;
    for (int32_t id : ids) out.push_back(culler.hidden(id));
    return out;
}

// Which probes the walls (the surfaces listed in `drawn`) hide.
std::vector<bool> hidden_probes(Walls& walls, const std::vector<uint32_t>& drawn,
                                const std::vector<Probe>& probes) {
    const nqr_brush_model model = walls.model();
    const SurfaceRange all{0, model.num_surfaces};
    OccluderMesh mesh(model, {&all, 1});
    OcclusionCuller culler(mesh);
    culler.begin_frame(eye_at_origin());
    const std::vector<int32_t> ids = add_probes(culler, probes);
    culler.rasterize_world(drawn);
    return verdicts(culler, ids);
}

TEST(EngineOcclusion, AWallHidesWhatIsBehindItAndNothingElse) {
    Walls walls;
    walls.add(100, -200, 200, -200, 200);
    const auto hidden = hidden_probes(walls, {0},
                                      {{300, 0, 0},       // behind
                                       {300, 0, 500},     // behind, but above the wall's top
                                       {60, 0, 0},        // in front
                                       {105, 0, 0},       // touching it from behind
                                       {2000, 150, 0}});  // far behind, near its side
    EXPECT_EQ(hidden, (std::vector<bool>{true, false, false, false, true}));
}

// A seam at this y, 100 units ahead, runs through the centres of pixel column 80:
// x = (1 - y / 100) * 80 = 80.5.
constexpr float kSeam = -0.625f;

TEST(EngineOcclusion, ASharedEdgeClosesTheSeamOnlyWhenBothFacesAreDrawn) {
    Walls walls;
    walls.add(100, -200, kSeam, -200, 200);
    walls.add(100, kSeam, 200, -200, 200);
    const std::vector<Probe> on_seam = {{300, 0, 0}, {300, 0, 100}};
    EXPECT_EQ(hidden_probes(walls, {0, 1}, on_seam), (std::vector<bool>{true, true}));
    // One half alone: its edge at the seam is an outline, the probes straddle it.
    EXPECT_EQ(hidden_probes(walls, {0}, on_seam), (std::vector<bool>{false, false}));
    EXPECT_EQ(hidden_probes(walls, {0}, {{300, -60, 0}}), (std::vector<bool>{true}));
}

TEST(EngineOcclusion, AnUnsharedSeamIsNeverCrossed) {
    // The same two halves with their own vertices (a T-junction or a crack): the GPU may leave
    // pixels open along the seam, so what lies behind it stays.
    Walls walls;
    walls.add(100, -200, kSeam, -200, 200, false);
    walls.add(100, kSeam, 200, -200, 200, false);
    EXPECT_EQ(hidden_probes(walls, {0, 1}, {{300, 0, 0}, {300, -60, 0}, {300, 60, 0}}),
              (std::vector<bool>{false, true, true}));
}

TEST(EngineOcclusion, SkyAndLiquidsHideNothing) {
    Walls walls;
    walls.add(100, -200, 200, -200, 200, true, NQR_SURFACE_SKY);
    walls.add(120, -200, 200, -200, 200, true, NQR_SURFACE_LIQUID);
    EXPECT_EQ(hidden_probes(walls, {0, 1}, {{300, 0, 0}}), (std::vector<bool>{false}));
}

TEST(EngineOcclusion, AFaceSeenFromBehindHidesNothing) {
    Walls walls;
    walls.add(100, -200, 200, -200, 200, true, 0, true);
    EXPECT_EQ(hidden_probes(walls, {0}, {{300, 0, 0}}), (std::vector<bool>{false}));
}

// A door: model 1 (surfaces 1 and 2, its two halves) placed by a translation; the world
// (model 0, surface 0) is a small wall elsewhere.
std::vector<bool> hidden_behind_door(const glm::vec3& door_offset, const std::vector<Probe>& probes,
                                     bool halves_in_one_model = true) {
    Walls walls;
    walls.add(100, 500, 600, -50, 50);     // world: far to the left, hides nothing here
    walls.add(0, -200, kSeam, -200, 200);  // door halves at x = 0 in their own space
    walls.add(0, kSeam, 200, -200, 200);
    const nqr_brush_model model = walls.model();
    const SurfaceRange one_model[] = {{0, 1}, {1, 2}};
    const SurfaceRange split[] = {{0, 1}, {1, 1}, {2, 1}};
    OccluderMesh mesh(model, halves_in_one_model ? std::span<const SurfaceRange>(one_model)
                                                 : std::span<const SurfaceRange>(split));
    OcclusionCuller culler(mesh);
    culler.begin_frame(eye_at_origin());
    const std::vector<int32_t> ids = add_probes(culler, probes);
    const uint32_t world_visible[] = {0};
    culler.rasterize_world(world_visible);
    glm::mat4 door(1.0f);
    door[3] = glm::vec4(door_offset, 1.0f);
    const glm::vec3 eye_in_door = glm::vec3(glm::inverse(door) * glm::vec4(0, 0, 0, 1));
    culler.rasterize_model(1, 2, door, eye_in_door);
    return verdicts(culler, ids);
}

TEST(EngineOcclusion, APlacedBrushModelHidesLikeTheWorld) {
    // Moved 100 units ahead, the door stands where the wall of the first test stood.
    EXPECT_EQ(hidden_behind_door({100, 0, 0}, {{300, 0, 0}, {300, -60, 0}, {60, 0, 0}}),
              (std::vector<bool>{true, true, false}));
    // Moved behind the eye it faces away: nothing is hidden.
    EXPECT_EQ(hidden_behind_door({-100, 0, 0}, {{300, 0, 0}}), (std::vector<bool>{false}));
    // Its halves meet along an edge only within one model: as two models the seam stays open.
    EXPECT_EQ(hidden_behind_door({100, 0, 0}, {{300, 0, 0}, {300, -60, 0}}, false),
              (std::vector<bool>{false, true}));
}

// Two walls 100 units ahead with a gap between them (|y| < 20), and an object of two
// triangles 300 units ahead: its rectangle spans the gap, its triangles lie behind the walls
// unless `third_in_gap` adds one behind the gap.
std::vector<bool> two_triangles_behind_two_walls(bool third_in_gap) {
    Walls walls;
    walls.add(100, 20, 200, -200, 200);
    walls.add(100, -200, -20, -200, 200);
    const nqr_brush_model model = walls.model();
    const SurfaceRange all{0, 2};
    OccluderMesh mesh(model, {&all, 1});
    OcclusionCuller culler(mesh);
    culler.begin_frame(eye_at_origin());
    std::vector<glm::vec3> points = {{300, 110, 0},  {300, 130, 0},  {300, 120, 20},
                                     {300, -110, 0}, {300, -130, 0}, {300, -120, 20}};
    if (third_in_gap) points.insert(points.end(), {{300, -5, 0}, {300, 5, 0}, {300, 0, 10}});
    const int32_t id = culler.add_points(glm::mat4(1.0f), points);
    const uint32_t drawn[] = {0, 1};
    culler.rasterize_world(drawn);
    std::vector<bool> out = {culler.hidden(id)};
    for (uint32_t t = 0; t < points.size() / 3; ++t) {
        out.push_back(culler.triangle_hidden(id, 3 * t, 3 * t + 1, 3 * t + 2));
    }
    return out;
}

TEST(EngineOcclusion, TrianglesAreHiddenOneByOneWhereTheirRectangleIsNot) {
    EXPECT_EQ(two_triangles_behind_two_walls(false), (std::vector<bool>{false, true, true}));
    EXPECT_EQ(two_triangles_behind_two_walls(true), (std::vector<bool>{false, true, true, false}));
}

// One wall 100 units ahead, its occluder mesh and a culler with a frame begun.
struct OneWall {
    OneWall() { culler.begin_frame(eye_at_origin()); }
    static Walls make() {
        Walls w;
        w.add(100, -200, 200, -200, 200);
        return w;
    }
    Walls walls = make();
    nqr_brush_model model = walls.model();
    SurfaceRange all{0, 1};
    OccluderMesh mesh{model, {&all, 1}};
    OcclusionCuller culler{mesh};
};

TEST(EngineOcclusion, DepthIsTheFacesDistanceAlongTheView) {
    OneWall wall;
    OcclusionCuller& culler = wall.culler;
    glm::mat4 placement(1.0f);
    placement[3] = glm::vec4(300.0f, 0.0f, 0.0f, 1.0f);
    // A box covering the whole view far away, so every pixel is rasterised.
    ASSERT_NE(culler.add_box(placement, glm::vec3(-10.0f, -400.0f, -300.0f),
                             glm::vec3(10.0f, 400.0f, 300.0f)),
              OcclusionCuller::kNotHideable);
    const uint32_t drawn[] = {0};
    culler.rasterize_world(drawn);
    for (int y : {0, 37, 60, 119}) {
        for (int x : {0, 80, 159}) {
            // A plane square to the view: w = 100 everywhere (pushed back by 1/100 unit).
            EXPECT_NEAR(culler.inverse_w_at(x, y), 1.0f / 100.0f, 2e-6f) << x << ", " << y;
        }
    }
}

TEST(EngineOcclusion, ABoxReachingPastTheNearPlaneIsNeverHidden) {
    OneWall wall;
    EXPECT_EQ(wall.culler.add_box(glm::mat4(1.0f), glm::vec3(-8.0f), glm::vec3(8.0f)),
              OcclusionCuller::kNotHideable);
}

// ------------------------------------------------------------------ both demos, against OpenGL

constexpr int kViewWidth = 320, kViewHeight = 240;

GLuint compile(GLenum stage, const char* source) {
    GLuint shader = glCreateShader(stage);
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    return shader;
}

// The frame's world drawn as the plugins draw it (back faces culled, GL_LESS), then models
// drawn with GL_LEQUAL inside an any-samples query.
class GpuDepthReference {
  public:
    GpuDepthReference() : target_(kViewWidth, kViewHeight) {
        program_ = glCreateProgram();
        const GLuint vs = compile(GL_VERTEX_SHADER,
                                  "#version 330 core\n"
                                  "layout(location = 0) in vec3 position;\n"
                                  "uniform mat4 view_projection;\n"
                                  "void main() { gl_Position = view_projection * "
                                  "vec4(position, 1.0); }\n");
        const GLuint fs = compile(GL_FRAGMENT_SHADER,
                                  "#version 330 core\nout vec4 colour;\n"
                                  "void main() { colour = vec4(1.0); }\n");
        glAttachShader(program_, vs);
        glAttachShader(program_, fs);
        glLinkProgram(program_);
        glDeleteShader(vs);
        glDeleteShader(fs);
        glGenVertexArrays(1, &vao_);
        glGenBuffers(1, &vertices_);
        glGenQueries(1, &query_);
    }
    ~GpuDepthReference() {
        glDeleteQueries(1, &query_);
        glDeleteBuffers(1, &vertices_);
        glDeleteVertexArrays(1, &vao_);
        glDeleteProgram(program_);
    }
    bool complete() const { return target_.complete(); }

    // The listed world surfaces that are opaque (not sky, liquid or fence), and those of the
    // opaque brush entities on screen, as triangle fans.
    void draw_world(const nqr_frame& frame, const Level& level) {
        const nqr_model& world = *level.models().get(frame.world)->abi();
        triangles_.clear();
        for (uint32_t i = 0; i < frame.num_visible_surfaces; ++i) {
            add_surface(*world.brush, frame.visible_surfaces[i], glm::mat4(1.0f));
        }
        for (uint32_t i = 0; i < frame.num_brush_entities; ++i) {
            const nqr_entity& e = *frame.brush_entities[i];
            const nqr_model& m = *level.models().get(e.model)->abi();
            if ((e.flags & NQR_ENTITY_OUTSIDE_VIEW) || (e.alpha > 0.0f && e.alpha < 1.0f)) continue;
            for (uint32_t s = m.first_surface; s < m.first_surface + m.num_surfaces; ++s) {
                add_surface(*m.brush, s, load_matrix(e.model_matrix));
            }
        }
        target_.bind();
        glDepthMask(GL_TRUE);
        glClearDepth(1.0);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glEnable(GL_CULL_FACE);
        glCullFace(GL_BACK);
        glFrontFace(GL_CCW);
        glUseProgram(program_);
        glUniformMatrix4fv(glGetUniformLocation(program_, "view_projection"), 1, GL_FALSE,
                           frame.camera->view_projection);
        draw_triangles();
    }

    void add_surface(const nqr_brush_model& brush, uint32_t surface, const glm::mat4& placement) {
        const nqr_surface& s = brush.surfaces[surface];
        if (s.flags & (NQR_SURFACE_SKY | NQR_SURFACE_LIQUID) || s.texture < 0) return;
        if (brush.textures[s.texture].name[0] == '{') return;
        for (uint32_t k = 1; k + 1 < s.num_vertices; ++k) {
            for (uint32_t v : {0u, k, k + 1}) {
                const float* p = brush.positions + size_t{s.first_vertex + v} * 3;
                triangles_.emplace_back(placement * glm::vec4(p[0], p[1], p[2], 1.0f));
            }
        }
    }

    // Whether any sample of the entity's blended pose passes the depth test against the world
    // (with GL_ALWAYS: whether it lands on screen at all).
    bool model_visible(const nqr_alias_model& a, const nqr_entity& e, GLenum depth_func) {
        const std::vector<glm::vec3> posed = test::blended_world_vertices(a, e);
        triangles_.clear();
        for (uint32_t t = 0; t < a.num_triangles; ++t) {
            for (int k = 1; k < 4; ++k) triangles_.push_back(posed[a.triangles[t * 4 + k]]);
        }
        glDisable(GL_CULL_FACE);
        glDepthMask(GL_FALSE);
        glDepthFunc(depth_func);
        glBeginQuery(GL_ANY_SAMPLES_PASSED, query_);
        draw_triangles();
        glEndQuery(GL_ANY_SAMPLES_PASSED);
        glEnable(GL_CULL_FACE);
        GLuint any = 1;
        glGetQueryObjectuiv(query_, GL_QUERY_RESULT, &any);
        return any != 0;
    }

  private:
    void draw_triangles() {
        glBindVertexArray(vao_);
        glBindBuffer(GL_ARRAY_BUFFER, vertices_);
        glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(triangles_.size() * sizeof(glm::vec3)),
                     triangles_.data(), GL_STREAM_DRAW);
        glEnableVertexAttribArray(0);
        glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
        glDrawArrays(GL_TRIANGLES, 0, GLsizei(triangles_.size()));
    }

    npr::test::SizedFramebuffer target_;
    GLuint program_ = 0, vao_ = 0, vertices_ = 0, query_ = 0;
    std::vector<glm::vec3> triangles_;
};

struct OcclusionReport {
    size_t on_screen = 0;        // alias entities the GPU draws samples of (not the weapon)
    size_t gpu_hidden = 0;       // ... none of which pass the depth test
    size_t flagged_hidden = 0;   // flagged NQR_ENTITY_OCCLUDED
    size_t flagged_off = 0;      // flagged NQR_ENTITY_OUTSIDE_VIEW
    size_t wrongly_flagged = 0;  // flagged, yet some sample reaches the screen
    std::string first_wrong;
};

class EngineOcclusionOnDemos : public npr::test::GlSuiteTest<EngineOcclusionOnDemos> {
  protected:
    OcclusionReport play(const std::string& demo, int frame_step) {
        Vfs vfs = test::mount_lq1();
        test::DemoReplay replay(vfs, demo + ".dem");
        GpuDepthReference gpu;
        EXPECT_TRUE(gpu.complete());
        SceneBuilder scene;
        uint32_t bound_generation = 0;
        OcclusionReport r;
        for (uint64_t frame = 1;; frame += frame_step) {
            const bool ready = replay.play_to(frame);
            if (replay.frames() < frame) break;
            if (!ready) continue;
            if (replay.client().generation() != bound_generation) {
                bound_generation = replay.client().generation();
                scene.bind_level(replay.level());
            }
            CameraSetup camera;
            camera.origin = {replay.view().origin[0], replay.view().origin[1],
                             replay.view().origin[2]};
            camera.angles = {replay.view().angles[0], replay.view().angles[1],
                             replay.view().angles[2]};
            camera.viewport[2] = kViewWidth;
            camera.viewport[3] = kViewHeight;
            const nqr_frame& f = scene.build(replay.level(), replay.client(), replay.view(), camera,
                                             double(frame) * 0.01, 0.01f);
            gpu.draw_world(f, replay.level());
            for (uint32_t i = 0; i < f.num_alias_entities; ++i) {
                const nqr_entity& e = *f.alias_entities[i];
                if (check_entity(replay.level(), e, gpu, r) && r.first_wrong.empty()) {
                    r.first_wrong = demo + " frame " + std::to_string(frame) + " entity " +
                                    std::to_string(e.number);
                }
            }
        }
        return r;
    }

    // False when the entity is flagged and the GPU draws some of it.
    static bool check_entity(const Level& level, const nqr_entity& e, GpuDepthReference& gpu,
                             OcclusionReport& r) {
        const RenderModel* model = level.models().get(e.model);
        if ((e.flags & NQR_ENTITY_VIEWMODEL) || !model || !model->alias_data()) return true;
        const nqr_alias_model& a = model->alias_data()->abi();
        if (e.pose0 >= a.num_poses || e.pose1 >= a.num_poses) return true;
        const bool on_screen = gpu.model_visible(a, e, GL_ALWAYS);
        const bool visible = on_screen && gpu.model_visible(a, e, GL_LEQUAL);
        r.on_screen += on_screen;
        r.gpu_hidden += on_screen && !visible;
        r.flagged_off += (e.flags & NQR_ENTITY_OUTSIDE_VIEW) != 0;
        r.flagged_hidden += (e.flags & NQR_ENTITY_OCCLUDED) != 0;
        const bool wrong = ((e.flags & NQR_ENTITY_OUTSIDE_VIEW) && on_screen) ||
                           ((e.flags & NQR_ENTITY_OCCLUDED) && visible);
        r.wrongly_flagged += wrong;
        return wrong;
    }
};

TEST_F(EngineOcclusionOnDemos, FlaggedModelsDrawNoSampleAndMostHiddenOnesAreFlagged) {
    for (const std::string demo : {"demo", "demo2"}) {
        const OcclusionReport r = play(demo, 2);
        std::printf(
            "%s: %zu alias entities on screen, %zu of them hidden by the world (GPU), %zu "
            "flagged occluded; %zu flagged outside the view\n",
            demo.c_str(), r.on_screen, r.gpu_hidden, r.flagged_hidden, r.flagged_off);
        EXPECT_GT(r.on_screen, 5000u) << demo;
        EXPECT_EQ(r.wrongly_flagged, 0u) << r.first_wrong;
        // The culler finds most of what the GPU hides (it gives up pixels along outlines and
        // T-junctions, and models reaching the near plane).
        EXPECT_GT(r.flagged_hidden, r.gpu_hidden * 8 / 10) << demo;
    }
}

}  // namespace
}  // namespace nq

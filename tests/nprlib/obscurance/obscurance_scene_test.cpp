// The obscurance reference's scene files (nprlib/obscurance/scene_file) and the frame geometry
// they carry (scene_triangles): a scene survives encoding, every malformed file is refused with
// the offset of its first bad byte, and a frame's world, brush and alias entities come out as
// the triangles computed here from the same ABI data (surfaces fanned, sky not solid, an alias
// pose blend placed by its matrix, the view model left out).
#include <cstring>
#include <limits>

#include <gtest/gtest.h>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "obscurance/scene_file.h"
#include "obscurance/scene_triangles.h"

namespace nq::npr::obscurance {
namespace {

ObscuranceScene two_triangles() {
    ObscuranceScene scene;
    scene.width = 320;
    scene.height = 200;
    for (int i = 0; i < 16; ++i) scene.projection[i] = float(i) * 0.5f;
    scene.triangles.push_back({{1, 2, 3}, {4, 5, 6}, {7, 8, 9}, true});
    scene.triangles.push_back({{-1, -2, -3}, {0.5f, 0.25f, 0}, {1e6f, -1e-6f, 2}, false});
    return scene;
}

void expect_same(const SceneTriangle& a, const SceneTriangle& b) {
    EXPECT_EQ(a.a, b.a);
    EXPECT_EQ(a.b, b.b);
    EXPECT_EQ(a.c, b.c);
    EXPECT_EQ(a.solid, b.solid);
}

TEST(ObscuranceSceneFile, ASceneSurvivesEncoding) {
    const ObscuranceScene scene = two_triangles();
    const std::vector<uint8_t> bytes = encode_scene(scene);
    ASSERT_EQ(bytes.size(), 84u + 2 * 40u);  // header, then 40 bytes a triangle
    EXPECT_EQ(std::string(bytes.begin(), bytes.begin() + 8), "NQVOSCN1");
    const SceneParse parsed = parse_scene(bytes, "a.bin");
    ASSERT_TRUE(parsed.scene) << parsed.error;
    EXPECT_EQ(parsed.scene->width, 320u);
    EXPECT_EQ(parsed.scene->height, 200u);
    EXPECT_EQ(0, std::memcmp(parsed.scene->projection, scene.projection, sizeof scene.projection));
    ASSERT_EQ(parsed.scene->triangles.size(), 2u);
    for (size_t i = 0; i < 2; ++i) expect_same(parsed.scene->triangles[i], scene.triangles[i]);
}

// The message names the file, the offset and the problem.
void expect_refused(const std::vector<uint8_t>& bytes, size_t offset, const std::string& problem) {
    const SceneParse parsed = parse_scene(bytes, "bad.bin");
    EXPECT_FALSE(parsed.scene);
    EXPECT_NE(parsed.error.find("bad.bin: offset " + std::to_string(offset) + ": "),
              std::string::npos)
        << parsed.error;
    EXPECT_NE(parsed.error.find(problem), std::string::npos) << parsed.error;
}

void put_u32(std::vector<uint8_t>& bytes, size_t at, uint32_t v) {
    for (int i = 0; i < 4; ++i) bytes[at + size_t(i)] = uint8_t(v >> (8 * i));
}

TEST(ObscuranceSceneFile, MalformedFilesAreRefusedAtTheirOffset) {
    const std::vector<uint8_t> good = encode_scene(two_triangles());
    expect_refused({good.begin(), good.begin() + 50}, 50, "header");
    std::vector<uint8_t> bytes = good;
    bytes[3] = 'X';
    expect_refused(bytes, 0, "magic");
    bytes = good;
    put_u32(bytes, 8, 0);
    expect_refused(bytes, 8, "viewport 0x200");
    bytes = good;
    put_u32(bytes, 12, kMaxSceneSide + 1);
    expect_refused(bytes, 8, "not within");
    bytes = good;
    put_u32(bytes, 80, 3);  // one triangle more than the file holds
    expect_refused(bytes, 80, "counts 3 triangles");
    bytes = good;
    put_u32(bytes, 80, 0xffffffffu);
    expect_refused(bytes, 80, "counts 4294967295");
    expect_refused({good.begin(), good.end() - 1}, 80, "counts 2");
    bytes = good;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    std::memcpy(&bytes[84 + 40 + 8], &nan, 4);  // the second triangle's a.z
    expect_refused(bytes, 84 + 40 + 8, "not a finite number");
    bytes = good;
    std::memcpy(&bytes[16 + 4 * 5], &nan, 4);  // projection[5]
    expect_refused(bytes, 36, "not a finite number");
    bytes = good;
    put_u32(bytes, 84 + 36, 6);  // the first triangle's flags
    expect_refused(bytes, 84 + 36, "unknown triangle flags 6");
}

// A frame built here: the world is one brush model with a quad (floor) and a sky triangle, a
// door is the same brush model's third surface placed by a matrix, an alias entity blends two
// poses of one triangle, and a view model is listed too.
class SceneTrianglesTest : public ::testing::Test {
  protected:
    void SetUp() override {
        const float quad[] = {0, 0, 0, 64, 0, 0, 64, 64, 0, 0, 64, 0};
        const float sky[] = {0, 0, 128, 64, 0, 128, 0, 64, 128};
        const float door[] = {0, 0, 0, 0, 0, 32, 0, 16, 32};
        positions_.insert(positions_.end(), std::begin(quad), std::end(quad));
        positions_.insert(positions_.end(), std::begin(sky), std::end(sky));
        positions_.insert(positions_.end(), std::begin(door), std::end(door));
        for (int i = 0; i < 3; ++i) {
            nqr_surface s{};
            s.size = sizeof(nqr_surface);
            s.first_vertex = i == 0 ? 0 : i == 1 ? 4 : 7;
            s.num_vertices = i == 0 ? 4 : 3;
            s.flags = i == 1 ? NQR_SURFACE_SKY : 0;
            surfaces_.push_back(s);
        }
        brush_.size = sizeof(brush_);
        brush_.num_surfaces = 3;
        brush_.surfaces = surfaces_.data();
        brush_.num_vertices = uint32_t(positions_.size() / 3);
        brush_.positions = positions_.data();
        world_ = model(1, NQR_MODEL_BRUSH);
        world_.brush = &brush_;
        world_.first_surface = 0;
        world_.num_surfaces = 2;
        door_model_ = model(2, NQR_MODEL_BRUSH);
        door_model_.brush = &brush_;
        door_model_.first_surface = 2;
        door_model_.num_surfaces = 1;

        poses_ = {{{10, 0, 0}, 0}, {{0, 10, 0}, 0}, {{0, 0, 10}, 0},
                  {{20, 0, 0}, 0}, {{0, 20, 0}, 0}, {{0, 0, 30}, 0}};
        triangles_ = {1, 0, 1, 2};
        alias_.size = sizeof(alias_);
        alias_.scale[0] = alias_.scale[1] = alias_.scale[2] = 0.5f;
        alias_.origin[2] = -4.0f;
        alias_.num_vertices = 3;
        alias_.num_triangles = 1;
        alias_.num_poses = 2;
        alias_.triangles = triangles_.data();
        alias_.poses = poses_.data();
        ogre_ = model(3, NQR_MODEL_ALIAS);
        ogre_.alias = &alias_;

        door_ = entity(2, glm::translate(glm::mat4(1.0f), glm::vec3(100, 0, 0)));
        monster_ = entity(3, glm::translate(glm::mat4(1.0f), glm::vec3(0, 200, 0)));
        monster_.pose0 = 0;
        monster_.pose1 = 1;
        monster_.lerp = 0.25f;
        gun_ = entity(3, glm::mat4(1.0f));
        gun_.flags = NQR_ENTITY_VIEWMODEL;
        brush_list_ = {&door_};
        alias_list_ = {&monster_, &gun_};

        view_ = glm::translate(glm::mat4(1.0f), glm::vec3(-5, -6, -300));
        frame_.size = sizeof(frame_);
        camera_.size = sizeof(camera_);
        frame_.camera = &camera_;
        std::copy_n(glm::value_ptr(view_), 16, camera_.view);
        const glm::mat4 projection = glm::perspective(1.2f, 4.0f / 3.0f, 4.0f, 4096.0f);
        std::copy_n(glm::value_ptr(projection), 16, camera_.projection);
        camera_.viewport[2] = 640;
        camera_.viewport[3] = 480;
        frame_.world = 1;
        frame_.brush_entities = brush_list_.data();
        frame_.num_brush_entities = 1;
        frame_.alias_entities = alias_list_.data();
        frame_.num_alias_entities = 2;
        models_ = {&world_, &door_model_, &ogre_};
    }

    static nqr_model model(nqr_model_id id, uint32_t kind) {
        nqr_model m{};
        m.size = sizeof(m);
        m.id = id;
        m.kind = kind;
        return m;
    }
    static nqr_entity entity(nqr_model_id model, const glm::mat4& placement) {
        nqr_entity e{};
        e.size = sizeof(e);
        static const nqr_entity_light kLight = [] {
            nqr_entity_light light{};
            light.size = sizeof light;
            return light;
        }();
        e.light = &kLight;
        e.model = model;
        std::copy_n(glm::value_ptr(placement), 16, e.model_matrix);
        return e;
    }
    glm::vec3 in_view(const glm::vec3& world) const {
        return glm::vec3(view_ * glm::vec4(world, 1.0f));
    }

    std::vector<float> positions_;
    std::vector<nqr_surface> surfaces_;
    nqr_brush_model brush_{};
    nqr_model world_{}, door_model_{}, ogre_{};
    std::vector<nqr_alias_vertex> poses_;
    std::vector<int32_t> triangles_;
    nqr_alias_model alias_{};
    nqr_entity door_{}, monster_{}, gun_{};
    std::vector<const nqr_entity*> brush_list_, alias_list_;
    glm::mat4 view_{1.0f};
    nqr_frame frame_{};
    nqr_camera camera_{};
    std::vector<const nqr_model*> models_;
};

TEST_F(SceneTrianglesTest, TheFrameComesOutAsItsTrianglesInViewSpace) {
    const ObscuranceScene scene = collect_scene(frame_, models_);
    EXPECT_EQ(scene.width, 640u);
    EXPECT_EQ(scene.height, 480u);
    EXPECT_EQ(0, std::memcmp(scene.projection, camera_.projection, sizeof scene.projection));
    // The quad fans into two, the sky is one (not solid), the door one, the monster one; the
    // gun none.
    ASSERT_EQ(scene.triangles.size(), 5u);
    expect_same(scene.triangles[0],
                {in_view({0, 0, 0}), in_view({64, 0, 0}), in_view({64, 64, 0}), true});
    expect_same(scene.triangles[1],
                {in_view({0, 0, 0}), in_view({64, 64, 0}), in_view({0, 64, 0}), true});
    expect_same(scene.triangles[2],
                {in_view({0, 0, 128}), in_view({64, 0, 128}), in_view({0, 64, 128}), false});
    expect_same(scene.triangles[3],
                {in_view({100, 0, 0}), in_view({100, 0, 32}), in_view({100, 16, 32}), true});
    // Pose 0 -> pose 1 at 0.25, then scale 0.5 and origin (0, 0, -4), then placed at y = 200.
    const auto monster = [&](glm::vec3 p0, glm::vec3 p1) {
        const glm::vec3 model = 0.5f * glm::mix(p0, p1, 0.25f) + glm::vec3(0, 0, -4);
        return in_view(model + glm::vec3(0, 200, 0));
    };
    const SceneTriangle& m = scene.triangles[4];
    EXPECT_TRUE(m.solid);
    EXPECT_LT(glm::distance(m.a, monster({10, 0, 0}, {20, 0, 0})), 1e-4f);
    EXPECT_LT(glm::distance(m.b, monster({0, 10, 0}, {0, 20, 0})), 1e-4f);
    EXPECT_LT(glm::distance(m.c, monster({0, 0, 10}, {0, 0, 30})), 1e-4f);
}

TEST_F(SceneTrianglesTest, BadIndicesAndUnknownModelsAddNothing) {
    triangles_ = {1, 0, 1, 3};  // vertex 3 of 3
    monster_.pose1 = 2;         // pose 2 of 2
    door_.model = 99;
    const ObscuranceScene scene = collect_scene(frame_, models_);
    EXPECT_EQ(scene.triangles.size(), 3u);  // the world's only
}

}  // namespace
}  // namespace nq::npr::obscurance

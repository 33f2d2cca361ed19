// ClassicRenderer's alias-model drawing (rendered offscreen, checked by pixels) and the CPU side
// it rests on: seam handling, computed pose normals (also on real LibreQuake models) and
// Quake's player colour translation.
#include <gtest/gtest.h>

#include <cmath>

#include "classic/alias_mesh.h"
#include "classic/classic_renderer.h"
#include "classic/player_colors.h"
#include "classic_renderer_suite.h"
#include "common/file_io.h"
#include "formats/mdl.h"
#include "support/nprlib_test_support.h"
#include "support/test_data.h"

namespace nq::npr::test {
namespace {

using classic::ClassicRenderer;

// ------------------------------------------------------------------ CPU: mesh and normals

TEST(AliasMesh, BackFacingTrianglesShiftSeamVerticesByHalfTheSkin) {
    AliasBuilder b;
    b.skin_width = 16;
    b.skin_height = 8;
    b.skin.assign(16 * 8, 1);
    b.st = {{1, 2, 3}, {0, 4, 5}, {0, 6, 7}};    // vertex 0 is on the seam
    b.triangles = {{1, 0, 1, 2}, {0, 0, 2, 1}};  // front-facing, then back-facing
    b.poses = {{{{0, 0, 0}}, {{10, 0, 0}}, {{0, 10, 0}}}};
    const auto mesh = classic::build_alias_mesh(*b.build());
    ASSERT_EQ(mesh.indices.size(), 6u);
    EXPECT_EQ(mesh.vertices.size(), 4u);  // vertex 0 twice: front and back of the seam
    const auto& front = mesh.vertices[mesh.indices[0]];
    const auto& back = mesh.vertices[mesh.indices[3]];
    EXPECT_EQ(front.pose_vertex, 0u);
    EXPECT_EQ(back.pose_vertex, 0u);
    EXPECT_FLOAT_EQ(front.uv[0], (2 + 0.5f) / 16);
    EXPECT_FLOAT_EQ(back.uv[0], (2 + 8 + 0.5f) / 16);
    EXPECT_FLOAT_EQ(back.uv[1], (3 + 0.5f) / 8);
    // The non-seam vertex 2 is shared by both triangles.
    EXPECT_EQ(mesh.indices[2], mesh.indices[4]);
}

TEST(AliasMesh, BoxNormalsPointOutOfTheBox) {
    AliasBuilder b;
    b.add_box_pose({0, 0, 0}, {16, 16, 16});
    b.skin.assign(64, 1);
    std::vector<float> normals;
    classic::compute_pose_normals(*b.build(), 0, normals);
    for (int corner = 0; corner < 8; ++corner) {
        const float expected = 1.0f / std::sqrt(3.0f);
        EXPECT_NEAR(normals[corner * 3 + 0], corner & 1 ? expected : -expected, 1e-5) << corner;
        EXPECT_NEAR(normals[corner * 3 + 1], corner & 2 ? expected : -expected, 1e-5) << corner;
        EXPECT_NEAR(normals[corner * 3 + 2], corner & 4 ? expected : -expected, 1e-5) << corner;
    }
}

TEST(AliasMesh, NormalPackingRoundTrips) {
    for (float v : {-1.0f, -0.5f, 0.0f, 0.3f, 1.0f}) {
        EXPECT_NEAR(classic::decode_normal_component(classic::encode_normal_component(v)), v,
                    1.0f / 127.0f);
    }
}

// Real models: the computed normal of most vertices points away from the model's centre
// (armour is convex; creatures mostly are). Independent of id's normal table.
TEST(AliasMesh, RealModelNormalsPointOutward) {
    struct Expectation {
        const char* name;
        double min_outward;
    };
    for (const Expectation& e : {Expectation{"armor.mdl", 0.95}, Expectation{"player.mdl", 0.6},
                                 Expectation{"backpack.mdl", 0.6}}) {
        const std::string path = nq::test::lq1_dir() + "/progs/" + e.name;
        auto bytes = nq::read_file(path);
        ASSERT_TRUE(bytes) << path;
        auto mdl = nq::parse_mdl(*bytes, path);
        ASSERT_TRUE(mdl) << path;
        const auto& pose = mdl->frames[0].poses[0];
        // The ABI view of pose 0.
        std::vector<int32_t> st, triangles;
        for (const auto& t : mdl->tex_coords) st.insert(st.end(), {t.on_seam, t.s, t.t});
        for (const auto& t : mdl->triangles) {
            triangles.insert(triangles.end(),
                             {t.faces_front, t.vertices[0], t.vertices[1], t.vertices[2]});
        }
        std::vector<nqr_alias_vertex> vertices;
        for (const auto& v : pose.vertices) vertices.push_back({{v.v[0], v.v[1], v.v[2]}, 0});
        nqr_alias_model model{};
        model.size = sizeof(model);
        std::copy_n(mdl->header.scale.data(), 3, model.scale);
        std::copy_n(mdl->header.scale_origin.data(), 3, model.origin);
        model.num_vertices = static_cast<uint32_t>(vertices.size());
        model.num_triangles = static_cast<uint32_t>(mdl->triangles.size());
        model.num_poses = 1;
        model.st = st.data();
        model.triangles = triangles.data();
        model.poses = vertices.data();
        std::vector<float> normals;
        classic::compute_pose_normals(model, 0, normals);

        const auto positions = nq::decoded_positions(mdl->header, pose);
        glm::vec3 centre(0.0f);
        for (const auto& p : positions) centre += glm::vec3(p[0], p[1], p[2]);
        centre /= static_cast<float>(positions.size());
        int outward = 0;
        for (size_t i = 0; i < positions.size(); ++i) {
            const glm::vec3 p(positions[i][0], positions[i][1], positions[i][2]);
            const glm::vec3 n(normals[i * 3], normals[i * 3 + 1], normals[i * 3 + 2]);
            EXPECT_NEAR(glm::length(n), 1.0f, 1e-4f);
            outward += glm::dot(n, p - centre) > 0.0f;
        }
        EXPECT_GE(outward, e.min_outward * static_cast<double>(positions.size())) << e.name;
    }
}

TEST(PlayerColours, ShirtAndPantsRangesMapToColourRows) {
    const classic::Translation t = classic::player_translation(4, 12);
    for (int k = 0; k < 16; ++k) {
        EXPECT_EQ(t[16 + k], 64 + k);        // colour 4: rows below 128 run forward
        EXPECT_EQ(t[96 + k], 192 + 15 - k);  // colour 12: rows from 128 run backward
    }
    for (int i : {0, 15, 32, 95, 112, 255}) EXPECT_EQ(t[i], i);
}

// ------------------------------------------------------------------ GPU drawing

// From (-64, 0, 0) looking along +X (screen right = world -Y).
nqr_camera side_camera() {
    return make_camera({-64.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 0.0f});
}

class ClassicAliasTest : public ClassicRendererSuite<ClassicAliasTest> {
  protected:
    // A 16-unit box centred on its origin; pose 1 is the same box 32 units along +Y.
    void register_box(nqr_model_id id, AliasBuilder& b, uint8_t skin_index) {
        b.add_box_pose({0, 0, 0}, {16, 16, 16});
        b.add_box_pose({0, 32, 0}, {16, 48, 16});
        b.origin = {-8.0f, -8.0f, -8.0f};
        b.skin.assign(64, skin_index);
        b.build();
        nqr_model model = b.model(id);
        renderer_.register_model(&model);
        ASSERT_NE(renderer_.models().find(id), nullptr);
    }

    std::vector<Rgb> draw(TestFrame& frame, const nqr_camera& camera, Rgb clear = {}) {
        gl_->clear(clear);
        renderer_.draw_alias_entities(frame.build(camera, 0));
        EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
        return gl_->pixels();
    }

    Rgb at(const nqr_camera& camera, glm::vec3 world) const {
        const glm::vec2 p = project(camera, world);
        return gl_->pixel(static_cast<int>(p.x), static_cast<int>(p.y));
    }
};

// Pixel bounds of the projected corners of the box [lo, hi].
Coverage projected_box(const nqr_camera& camera, glm::vec3 lo, glm::vec3 hi) {
    Coverage c;
    for (int i = 0; i < 8; ++i) {
        const glm::vec2 p =
            project(camera, {i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z});
        c.min_x = std::min(c.min_x, static_cast<int>(std::lround(p.x)));
        c.max_x = std::max(c.max_x, static_cast<int>(std::lround(p.x)) - 1);
        c.min_y = std::min(c.min_y, static_cast<int>(std::lround(p.y)));
        c.max_y = std::max(c.max_y, static_cast<int>(std::lround(p.y)) - 1);
    }
    return c;
}

void expect_bounds_near(const Coverage& drawn, const Coverage& expected) {
    EXPECT_NEAR(drawn.min_x, expected.min_x, 1);
    EXPECT_NEAR(drawn.max_x, expected.max_x, 1);
    EXPECT_NEAR(drawn.min_y, expected.min_y, 1);
    EXPECT_NEAR(drawn.max_y, expected.max_y, 1);
}

TEST_F(ClassicAliasTest, ModelAppearsWhereProjectedAndLerpMovesItHalfway) {
    AliasBuilder b;
    register_box(1, b, colour::kRed);
    nqr_entity entity = make_entity(1);
    entity.flags = NQR_ENTITY_FULLBRIGHT;
    entity.pose0 = 0;
    entity.pose1 = 1;
    TestFrame frame;
    frame.alias.push_back(&entity);
    const nqr_camera camera = side_camera();

    entity.lerp = 0.0f;
    const Coverage at_pose0 = coverage(draw(frame, camera), {});
    expect_bounds_near(at_pose0, projected_box(camera, glm::vec3(-8), glm::vec3(8)));
    EXPECT_TRUE(near(at(camera, {-8, 0, 0}), colour(colour::kRed), 2));
    EXPECT_EQ(gl_->pixel(2, 2), (Rgb{0, 0, 0}));

    entity.lerp = 1.0f;
    const Coverage at_pose1 = coverage(draw(frame, camera), {});
    expect_bounds_near(at_pose1, projected_box(camera, {-8, 24, -8}, {8, 40, 8}));

    // Halfway between the poses looks exactly like pose 0 moved 16 units along +Y.
    entity.lerp = 0.5f;
    const std::vector<Rgb> halfway = draw(frame, camera);
    expect_bounds_near(coverage(halfway, {}), projected_box(camera, {-8, 8, -8}, {8, 24, 8}));
    nqr_entity moved = make_entity(1, glm::translate(glm::mat4(1.0f), {0.0f, 16.0f, 0.0f}));
    moved.flags = NQR_ENTITY_FULLBRIGHT;
    frame.alias = {&moved};
    const std::vector<Rgb> translated = draw(frame, camera);
    int different = 0;
    for (size_t i = 0; i < halfway.size(); ++i) different += !near(halfway[i], translated[i], 2);
    EXPECT_LE(different, 4);
}

TEST_F(ClassicAliasTest, EntityMatrixPlacesTheModel) {
    AliasBuilder b;
    register_box(1, b, colour::kRed);
    nqr_entity entity = make_entity(1, glm::translate(glm::mat4(1.0f), {0.0f, -24.0f, 12.0f}));
    entity.flags = NQR_ENTITY_FULLBRIGHT;
    TestFrame frame;
    frame.alias.push_back(&entity);
    const nqr_camera camera = side_camera();
    const Coverage c = coverage(draw(frame, camera), {});
    expect_bounds_near(c, projected_box(camera, {-8, -32, 4}, {8, -16, 20}));
}

TEST_F(ClassicAliasTest, LitSideIsBrighterAboveAnAmbientFloor) {
    AliasBuilder b;
    register_box(1, b, 150);
    nqr_entity entity = make_entity(1);
    nqr_entity_light light = make_light();
    light.ambient = 0.5f;
    light.directional = 1.0f;
    light.direction[0] = -1.0f;  // the light is on the -X side
    light.direction[2] = 0.0f;
    entity.light = &light;
    TestFrame frame;
    frame.alias.push_back(&entity);
    // From (-48, -48, 0) looking at the origin: the -X and -Y faces are visible.
    const nqr_camera camera = make_camera({-48.0f, -48.0f, 0.0f}, {0.0f, 45.0f, 0.0f});
    draw(frame, camera);
    const Rgb lit_face = at(camera, {-8.0f, 0.0f, 0.0f});
    const Rgb side_face = at(camera, {0.0f, -8.0f, 0.0f});
    // Smooth corner normals (+-1, +-1, +-1)/sqrt3: the -X face gets 0.5 + 1/sqrt3 everywhere,
    // the -Y face's centre the mean of 0.5 + 1/sqrt3 and 0.5.
    const double k = 1.0 / std::sqrt(3.0);
    EXPECT_NEAR(lit_face.r, 150 * (0.5 + k), 3.0);
    EXPECT_NEAR(side_face.r, 150 * (0.5 + k / 2), 3.0);
    EXPECT_GT(lit_face.r, side_face.r + 15);
}

TEST_F(ClassicAliasTest, LightColourTintsTheModel) {
    AliasBuilder b;
    register_box(1, b, 150);
    nqr_entity entity = make_entity(1);
    nqr_entity_light light = make_light();
    light.color[1] = light.color[2] = 0.5f;
    entity.light = &light;
    TestFrame frame;
    frame.alias.push_back(&entity);
    const nqr_camera camera = side_camera();
    draw(frame, camera);
    const Rgb face = at(camera, {-8, 0, 0});
    EXPECT_NEAR(face.r, 150, 2);
    EXPECT_NEAR(face.g, 75, 2);
}

TEST_F(ClassicAliasTest, FullbrightSkinPixelsIgnoreLight) {
    AliasBuilder bright, plain;
    register_box(1, bright, colour::kFullbrightGreen);
    register_box(2, plain, colour::kOrange);
    nqr_entity lamp = make_entity(1, glm::translate(glm::mat4(1.0f), {0.0f, 20.0f, 0.0f}));
    nqr_entity crate = make_entity(2, glm::translate(glm::mat4(1.0f), {0.0f, -20.0f, 0.0f}));
    nqr_entity_light dark = make_light();
    dark.ambient = dark.directional = 0.0f;
    for (nqr_entity* e : {&lamp, &crate}) e->light = &dark;
    TestFrame frame;
    frame.alias = {&lamp, &crate};
    const nqr_camera camera = side_camera();
    draw(frame, camera, {5, 5, 5});
    EXPECT_TRUE(near(at(camera, {-8, 20, 0}), colour(colour::kFullbrightGreen), 2));
    EXPECT_EQ(at(camera, {-8, -20, 0}), (Rgb{0, 0, 0}));  // drawn, unlit: black
}

TEST_F(ClassicAliasTest, PlayerColoursTranslateShirtAndPants) {
    AliasBuilder shirt, pants;
    register_box(1, shirt, colour::kShirtBase + 5);
    register_box(2, pants, colour::kPantsBase + 3);
    nqr_entity a = make_entity(1, glm::translate(glm::mat4(1.0f), {0.0f, 20.0f, 0.0f}));
    nqr_entity c = make_entity(2, glm::translate(glm::mat4(1.0f), {0.0f, -20.0f, 0.0f}));
    TestFrame frame;
    frame.alias = {&a, &c};
    for (nqr_entity* e : {&a, &c}) e->flags = NQR_ENTITY_FULLBRIGHT;
    const nqr_camera camera = side_camera();

    draw(frame, camera);  // no translation: the skin's own green and blue ramps
    EXPECT_TRUE(near(at(camera, {-8, 20, 0}), colour(colour::kShirtBase + 5), 2));
    EXPECT_TRUE(near(at(camera, {-8, -20, 0}), colour(colour::kPantsBase + 3), 2));

    for (nqr_entity* e : {&a, &c}) {
        e->has_translation = 1;
        e->top_color = 4;      // red row 64..79, forward
        e->bottom_color = 12;  // yellow row 192..207, reversed
    }
    draw(frame, camera);
    EXPECT_TRUE(near(at(camera, {-8, 20, 0}), colour(colour::kRedRow + 5), 2))
        << at(camera, {-8, 20, 0});
    EXPECT_TRUE(near(at(camera, {-8, -20, 0}), colour(colour::kYellowRow + 15 - 3), 2))
        << at(camera, {-8, -20, 0});

    // Same colours next frame: served from the cache, no new upload.
    const int uploads = renderer_.alias_drawer().translated_skins().uploads();
    draw(frame, camera);
    EXPECT_EQ(renderer_.alias_drawer().translated_skins().uploads(), uploads);
}

TEST_F(ClassicAliasTest, ViewModelDrawsInFrontOfNearerGeometry) {
    AliasBuilder box, wall;
    register_box(1, box, colour::kRed);
    wall.add_box_pose({0, 0, 0}, {2, 64, 64});
    wall.origin = {-1.0f, -32.0f, -32.0f};
    wall.skin.assign(64, colour::kBlue);
    wall.build();
    nqr_model wall_model = wall.model(2);
    renderer_.register_model(&wall_model);

    nqr_entity weapon = make_entity(1);
    nqr_entity blocker = make_entity(2, glm::translate(glm::mat4(1.0f), {-30.0f, 0.0f, 0.0f}));
    for (nqr_entity* e : {&weapon, &blocker}) e->flags = NQR_ENTITY_FULLBRIGHT;
    TestFrame frame;
    frame.alias = {&weapon, &blocker};
    const nqr_camera camera = side_camera();
    draw(frame, camera);
    EXPECT_TRUE(near(at(camera, {-8, 0, 0}), colour(colour::kBlue), 2));  // hidden by the wall

    weapon.flags |= NQR_ENTITY_VIEWMODEL;
    draw(frame, camera);
    EXPECT_TRUE(near(at(camera, {-8, 0, 0}), colour(colour::kRed), 2));
}

TEST_F(ClassicAliasTest, TranslucentEntityBlendsWithWhatIsBehind) {
    AliasBuilder b;
    register_box(1, b, colour::kRed);
    nqr_entity entity = make_entity(1);
    entity.flags = NQR_ENTITY_FULLBRIGHT;
    entity.alpha = 0.5f;
    TestFrame frame;
    frame.alias.push_back(&entity);
    const nqr_camera camera = side_camera();
    const Rgb background{0, 100, 0};
    draw(frame, camera, background);
    const Rgb red = colour(colour::kRed);
    const Rgb expected{red.r / 2, (red.g + background.g) / 2, (red.b + background.b) / 2};
    EXPECT_TRUE(near(at(camera, {-8, 0, 0}), expected, 3)) << at(camera, {-8, 0, 0});
}

}  // namespace
}  // namespace nq::npr::test

// ClassicRenderer on real LibreQuake data, through the engine's own ABI views (engine/render):
// every map draws from its player start without GL errors and shows a lit scene; every alias
// model and sprite registers and appears in front of the camera; shutdown frees everything.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "classic/classic_renderer.h"
#include "common/file_io.h"
#include "formats/bsp.h"
#include "formats/entities.h"
#include "formats/mdl.h"
#include "formats/palette.h"
#include "formats/spr.h"
#include "nprlib_test_support.h"
#include "render/alias_model.h"
#include "render/brush_model.h"
#include "render/sprite_model.h"
#include "support/test_data.h"

namespace nq::npr::test {
namespace {

using classic::ClassicRenderer;

std::vector<uint8_t> read_or_fail(const std::string& path) {
    auto bytes = nq::read_file(path);
    if (!bytes) throw std::runtime_error("cannot read " + path);
    return std::move(*bytes);
}

class ClassicRealDataTest : public GlSuiteTest<ClassicRealDataTest> {
  protected:
    void SetUp() override {
        GlSuiteTest::SetUp();
        if (HasFatalFailure()) return;
        const std::string path = nq::test::lq1_dir() + "/gfx/palette.lmp";
        auto palette = nq::parse_palette(read_or_fail(path), path);
        ASSERT_TRUE(palette) << path;
        for (int i = 0; i < 256; ++i) {
            engine_.palette[i * 3] = palette->colors[i].r;
            engine_.palette[i * 3 + 1] = palette->colors[i].g;
            engine_.palette[i * 3 + 2] = palette->colors[i].b;
        }
        std::string error;
        ASSERT_TRUE(renderer_.init(&engine_.engine, &error)) << error;
    }

    void TearDown() override {
        renderer_.shutdown();
        EXPECT_EQ(renderer_.live_gl_objects(), 0);
    }

    TestEngine engine_;
    ClassicRenderer renderer_;
};

TEST_F(ClassicRealDataTest, EveryMapDrawsALitSceneFromItsPlayerStart) {
    int maps = 0;
    for (const std::string& path : nq::test::lq1_files("maps", ".bsp")) {
        if (std::filesystem::path(path).filename().string().rfind("b_", 0) == 0) continue;
        SCOPED_TRACE(path);
        auto bsp = nq::parse_bsp(read_or_fail(path), path);
        ASSERT_TRUE(bsp);
        auto entities = nq::parse_entities(bsp->entities, path);
        ASSERT_TRUE(entities);
        const auto starts = nq::find_entities(*entities, "info_player_start");
        const auto deathmatch = nq::find_entities(*entities, "info_player_deathmatch");
        const nq::Entity* start = !starts.empty()      ? starts[0]
                                  : deathmatch.empty() ? nullptr
                                                       : deathmatch[0];
        ASSERT_NE(start, nullptr);
        const auto origin = nq::find_vec3(*start, "origin");
        ASSERT_TRUE(origin);
        float yaw = 0.0f;
        if (auto angle = nq::find_value(*start, "angle")) yaw = std::stof(std::string(*angle));

        auto data = nq::BrushModelData::build(std::move(*bsp));
        nqr_model world{};
        world.size = sizeof(world);
        world.id = 1;
        world.kind = NQR_MODEL_BRUSH;
        world.name = "world";
        world.brush = &data->abi();
        world.num_surfaces = static_cast<uint32_t>(data->bsp().models[0].num_faces);
        renderer_.register_model(&world);
        const auto* registered = renderer_.models().find(1);
        ASSERT_NE(registered, nullptr);
        EXPECT_LE(registered->brush->lightmap_pages(), 16);

        TestFrame frame;  // no visible list: every world surface
        const glm::vec3 eye((*origin)[0], (*origin)[1], (*origin)[2] + 22.0f);
        const nqr_camera camera = make_camera(eye, {10.0f, yaw, 0.0f});
        for (int n = 0; n < 2; ++n) {
            gl_->clear();
            renderer_.draw_world(frame.build(camera, 1, 0.5 * n));
        }
        EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
        gl_->dump_if_requested(std::filesystem::path(path).stem().string());
        const std::vector<Rgb> pixels = gl_->pixels();
        const Coverage lit = coverage(pixels, {}, 6);
        EXPECT_GT(lit.count, kSize * kSize / 2);
        int brightest = 0;
        for (const Rgb& p : pixels) brightest = std::max(brightest, brightness(p));
        EXPECT_GT(brightest, 150);
        renderer_.release_model(1);
        ++maps;
    }
    EXPECT_GE(maps, 1);
}

TEST_F(ClassicRealDataTest, EveryAliasModelAndSpriteRegistersAndAppears) {
    int models = 0;
    const nqr_camera camera = make_camera({0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 0.0f});
    for (const std::string& path : nq::test::lq1_files("progs", ".mdl")) {
        SCOPED_TRACE(path);
        auto mdl = nq::parse_mdl(read_or_fail(path), path);
        ASSERT_TRUE(mdl);
        const float radius = std::max(mdl->header.bounding_radius, 8.0f);
        auto data = nq::AliasModelData::build(std::move(*mdl));
        nqr_model model{};
        model.size = sizeof(model);
        model.id = 2;
        model.kind = NQR_MODEL_ALIAS;
        model.name = path.c_str();
        model.alias = &data->abi();
        renderer_.register_model(&model);
        ASSERT_NE(renderer_.models().find(2), nullptr);
        // In front of the camera, far enough for its radius to fit the view.
        nqr_entity entity =
            make_entity(2, glm::translate(glm::mat4(1.0f), {radius * 2.0f, 0.0f, 0.0f}));
        entity.flags = NQR_ENTITY_FULLBRIGHT;
        TestFrame frame;
        frame.alias.push_back(&entity);
        gl_->clear({1, 2, 3});
        renderer_.draw_alias_entities(frame.build(camera, 0));
        EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
        EXPECT_GT(coverage(gl_->pixels(), {1, 2, 3}, 0).count, 0);
        renderer_.release_model(2);
        ++models;
    }
    for (const std::string& path : nq::test::lq1_files("progs", ".spr")) {
        SCOPED_TRACE(path);
        auto spr = nq::parse_spr(read_or_fail(path), path);
        ASSERT_TRUE(spr);
        auto data = nq::SpriteModelData::build(std::move(*spr));
        nqr_model model{};
        model.size = sizeof(model);
        model.id = 3;
        model.kind = NQR_MODEL_SPRITE;
        model.name = path.c_str();
        model.sprite = &data->abi();
        renderer_.register_model(&model);
        ASSERT_NE(renderer_.models().find(3), nullptr);
        nqr_entity entity = make_entity(3, glm::translate(glm::mat4(1.0f), {64.0f, 0.0f, 0.0f}));
        TestFrame frame;
        frame.sprite.push_back(&entity);
        gl_->clear({1, 2, 3});
        renderer_.draw_sprite_entities(frame.build(camera, 0));
        EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
        EXPECT_GT(coverage(gl_->pixels(), {1, 2, 3}, 0).count, 0);
        renderer_.release_model(3);
        ++models;
    }
    EXPECT_GE(models, 10);
}

}  // namespace
}  // namespace nq::npr::test

// ClassicRenderer on real LibreQuake data, through the engine's own ABI views (engine/render):
// every map draws from its player start without GL errors and shows the light its own lightmaps
// predict there (a ray cast through the BSP here, pixel by pixel: texel x light); every alias
// model and sprite registers and appears in front of the camera; shutdown frees everything.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <filesystem>
#include <iostream>

#include "classic/classic_renderer.h"
#include "common/file_io.h"
#include "formats/bsp.h"
#include "formats/entities.h"
#include "formats/mdl.h"
#include "formats/palette.h"
#include "formats/spr.h"
#include "support/nprlib_test_support.h"
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

// ------------------------------------------------------------------ what the map's data predicts

constexpr double kDrawnTime = 0.5;  // the time of the frame that is read back (animations)

// What a pixel shows according to the map's own data, found without the renderer: the first
// world face along the pixel's ray (front faces only, as drawn), the texel there (mip 0, the
// texture's frame at `time`) and Quake's light at that point (QuakeSpasm's gl_overbright 1: the
// styles' samples x 264/256 summed, clamped to 255, bilinear between samples 16 texels apart,
// then x 2 / 255; the palette's last 32 colours are fullbright and unlit). Sky and liquids are
// drawn unlit and animated; they are only told apart here.
enum class Seen { nothing, lit, sky, liquid };

struct Predicted {
    Seen seen = Seen::nothing;
    glm::vec3 rgb{0.0f};  // 0..255 per channel, lit pixels only
};

class MapLightPredictor {
  public:
    MapLightPredictor(const nq::Bsp& bsp, const std::array<uint8_t, 768>& palette, double time)
        : bsp_(bsp), palette_(palette), time_(time) {
        polygons_.resize(bsp.faces.size());
        for (size_t f = 0; f < bsp.faces.size(); ++f) {
            const nq::BspFace& face = bsp.faces[f];
            for (uint32_t k = 0; k < face.num_surfedges; ++k) {
                const int32_t surfedge = bsp.surfedges[face.first_surfedge + k];
                const uint32_t v =
                    surfedge >= 0 ? bsp.edges[surfedge].v[0] : bsp.edges[-surfedge].v[1];
                polygons_[f].push_back(to_vec(bsp.vertices[v]));
            }
        }
    }

    Predicted pixel(const nqr_camera& camera, float x, float y) const {
        const glm::mat4 inverse = glm::inverse(glm::make_mat4(camera.view_projection));
        const glm::vec2 ndc = glm::vec2(x, y) / static_cast<float>(kSize) * 2.0f - 1.0f;
        const glm::vec4 far_point = inverse * glm::vec4(ndc, 1.0f, 1.0f);
        const glm::vec3 eye = glm::make_vec3(camera.origin);
        Hit hit;
        if (!trace(bsp_.models[0].headnodes[0], eye, glm::vec3(far_point) / far_point.w, hit)) {
            return {};
        }
        return shade(hit);
    }

  private:
    struct Hit {
        uint32_t face = 0;
        glm::vec3 point{0.0f};
    };

    static glm::vec3 to_vec(const nq::BspVec3& v) { return {v[0], v[1], v[2]}; }

    // Quake's RecursiveLightPoint, for any segment: the near side first, then the faces on the
    // node's plane where the segment crosses it, then the far side.
    bool trace(int32_t node_index, glm::vec3 start, glm::vec3 end, Hit& hit) const {
        if (node_index < 0) return false;
        const nq::BspNode& node = bsp_.nodes[node_index];
        const nq::BspPlane& plane = bsp_.planes[node.plane];
        const glm::vec3 normal = to_vec(plane.normal);
        const float front = glm::dot(normal, start) - plane.dist;
        const float back = glm::dot(normal, end) - plane.dist;
        const int side = front < 0.0f ? 1 : 0;
        if ((back < 0.0f ? 1 : 0) == side) return trace(node.children[side], start, end, hit);
        const glm::vec3 mid = start + (end - start) * (front / (front - back));
        if (trace(node.children[side], start, mid, hit)) return true;
        for (uint32_t f = node.first_face; f < node.first_face + node.num_faces; ++f) {
            if (bsp_.faces[f].back_side != (side == 1)) continue;  // seen from behind: culled
            if (inside(f, normal, mid)) {
                hit = {f, mid};
                return true;
            }
        }
        return trace(node.children[1 - side], mid, end, hit);
    }

    bool inside(uint32_t face, glm::vec3 normal, glm::vec3 p) const {
        const std::vector<glm::vec3>& polygon = polygons_[face];
        float sign = 0.0f;
        for (size_t i = 0; i < polygon.size(); ++i) {
            const glm::vec3 a = polygon[i], b = polygon[(i + 1) % polygon.size()];
            const float turn = glm::dot(glm::cross(b - a, p - a), normal);
            if (std::abs(turn) < 1e-3f) continue;  // on this side's line: inside enough
            if (sign == 0.0f) sign = turn;
            if ((turn > 0.0f) != (sign > 0.0f)) return false;
        }
        return true;
    }

    const nq::BspTexture& texture_at_time(uint32_t index) const {
        const nq::BspTexture& texture = bsp_.textures[index];
        if (texture.name.size() < 2 || texture.name[0] != '+' || texture.name[1] < '0' ||
            texture.name[1] > '9') {
            return texture;
        }
        std::vector<const nq::BspTexture*> frames;
        for (char frame = '0'; frame <= '9'; ++frame) {
            const std::string name = "+" + std::string(1, frame) + texture.name.substr(2);
            const auto found =
                std::find_if(bsp_.textures.begin(), bsp_.textures.end(),
                             [&](const nq::BspTexture& t) { return t.name == name; });
            if (found == bsp_.textures.end()) break;
            frames.push_back(&*found);
        }
        if (frames.empty()) return texture;
        return *frames[static_cast<size_t>(time_ * 5.0) % frames.size()];  // 5 frames a second
    }

    Predicted shade(const Hit& hit) const {
        const nq::BspFace& face = bsp_.faces[hit.face];
        const nq::BspTexinfo& texinfo = bsp_.texinfo[face.texinfo];
        const nq::BspTexture& texture = texture_at_time(texinfo.miptex);
        std::string name = texture.name;
        std::transform(name.begin(), name.end(), name.begin(),
                       [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
        if (name.rfind("sky", 0) == 0) return {Seen::sky, {}};
        if (name.rfind('*', 0) == 0) return {Seen::liquid, {}};
        float st[2];
        for (int axis = 0; axis < 2; ++axis) {
            const auto& v = texinfo.vecs[axis];
            st[axis] = hit.point.x * v[0] + hit.point.y * v[1] + hit.point.z * v[2] + v[3];
        }
        const nq::BspMipLevel& mip = texture.mips[0];
        const auto wrap = [](float value, uint32_t size) {
            const int64_t i = static_cast<int64_t>(std::floor(value)) % size;
            return static_cast<uint32_t>(i < 0 ? i + size : i);
        };
        const uint8_t index =
            mip.pixels[wrap(st[1], mip.height) * mip.width + wrap(st[0], mip.width)];
        const glm::vec3 colour(palette_[index * 3], palette_[index * 3 + 1],
                               palette_[index * 3 + 2]);
        if (index >= 224) return {Seen::lit, colour};  // fullbright
        return {Seen::lit, glm::min(colour * light(face, st) * 2.0f / 255.0f, glm::vec3(255.0f))};
    }

    // 0..255, Quake's stored lightmap value at texel coordinates st.
    float light(const nq::BspFace& face, const float st[2]) const {
        if (!face.has_lightmap() || bsp_.lighting.empty())
            return bsp_.lighting.empty() ? 255.0f : 0.0f;
        const int width = static_cast<int>(face.lightmap_width);
        const int height = static_cast<int>(face.lightmap_height);
        const float u = std::clamp((st[0] - face.texture_mins[0]) / 16.0f, 0.0f, width - 1.0f);
        const float v = std::clamp((st[1] - face.texture_mins[1]) / 16.0f, 0.0f, height - 1.0f);
        const int u0 = std::min(static_cast<int>(u), width - 1),
                  v0 = std::min(static_cast<int>(v), height - 1);
        const int u1 = std::min(u0 + 1, width - 1), v1 = std::min(v0 + 1, height - 1);
        const float fu = u - u0, fv = v - v0;
        // Each sample as the lightmap stores it, then filtered between the four around st.
        const auto stored = [&](int su, int sv) {
            float sum = 0.0f;
            for (uint32_t style = 0; style < face.num_styles; ++style) {
                const size_t at = static_cast<size_t>(face.light_offset) +
                                  style * face.lightmap_samples() + sv * width + su;
                if (at < bsp_.lighting.size()) sum += bsp_.lighting[at] * 264.0f / 256.0f;
            }
            return std::min(sum, 255.0f);  // style 'm' is 264 / 256
        };
        const float top = stored(u0, v0) * (1 - fu) + stored(u1, v0) * fu;
        const float bottom = stored(u0, v1) * (1 - fu) + stored(u1, v1) * fu;
        return top * (1 - fv) + bottom * fv;
    }

    const nq::Bsp& bsp_;
    const std::array<uint8_t, 768>& palette_;
    double time_;
    std::vector<std::vector<glm::vec3>> polygons_;
};

// The rendered image against what the map's light predicts (MapLightPredictor) on every other
// pixel of every other row, where the prediction is a lit face: the mean brightness and the
// share of pixels above black agree closely, and so do most 16 x 16 blocks (texture filtering
// and the pixels where faces meet blur single pixels, not blocks); no pixel is brighter than
// the brightest texel x light of the prediction. A dim start stays dim and a bright one bright;
// lightmaps missing, misplaced or scaled wrongly, or textures drawn unlit, fail.
void check_against_the_maps_light(const std::vector<Rgb>& pixels, const nq::Bsp& bsp,
                                  const nqr_camera& camera,
                                  const std::array<uint8_t, 768>& palette) {
    constexpr int kStep = 2, kBlock = 16, kBlocks = kSize / kBlock;
    const MapLightPredictor predictor(bsp, palette, kDrawnTime);
    int samples = 0, lit = 0, lit_rendered = 0, lit_predicted = 0;
    double sum_rendered = 0.0, sum_predicted = 0.0;
    float brightest_predicted = 0.0f;
    int brightest_rendered = 0;
    std::array<double, kBlocks * kBlocks> block_rendered{}, block_predicted{};
    std::array<int, kBlocks * kBlocks> block_lit{};
    for (int y = 0; y < kSize; y += kStep) {
        for (int x = 0; x < kSize; x += kStep) {
            ++samples;
            const Predicted predicted = predictor.pixel(camera, x + 0.5f, y + 0.5f);
            if (predicted.seen != Seen::lit) continue;
            const int rendered = brightness(pixels[y * kSize + x]);
            const float expected = predicted.rgb.r + predicted.rgb.g + predicted.rgb.b;
            ++lit;
            lit_rendered += rendered > 6;
            lit_predicted += expected > 6.0f;
            sum_rendered += rendered;
            sum_predicted += expected;
            brightest_rendered = std::max(brightest_rendered, rendered);
            brightest_predicted = std::max(brightest_predicted, expected);
            const int block = (y / kBlock) * kBlocks + x / kBlock;
            block_rendered[block] += rendered;
            block_predicted[block] += expected;
            ++block_lit[block];
        }
    }
    ASSERT_GE(lit, samples / 4) << "the start should look at lit faces";
    const double mean_rendered = sum_rendered / lit, mean_predicted = sum_predicted / lit;
    EXPECT_NEAR(mean_rendered, mean_predicted, 0.05 * mean_predicted + 2.0);
    EXPECT_NEAR(double(lit_rendered) / lit, double(lit_predicted) / lit, 0.05);
    EXPECT_LE(brightest_rendered, brightest_predicted * 1.03f + 6.0f);
    int blocks = 0, blocks_off = 0;
    for (int b = 0; b < kBlocks * kBlocks; ++b) {
        if (block_lit[b] < (kBlock / kStep) * (kBlock / kStep) / 2) continue;  // half lit or more
        ++blocks;
        const double rendered = block_rendered[b] / block_lit[b];
        const double predicted = block_predicted[b] / block_lit[b];
        if (std::abs(rendered - predicted) > 0.15 * predicted + 4.0) ++blocks_off;
    }
    EXPECT_GE(blocks, kBlocks * kBlocks / 4);
    EXPECT_LE(blocks_off, blocks / 10);
    std::cout << "[ classic ] " << std::filesystem::path(bsp.name).filename().string()
              << ": mean brightness " << mean_rendered << " (the map's light predicts "
              << mean_predicted << "), brightest " << brightest_rendered << " ("
              << brightest_predicted << "), blocks off " << blocks_off << " of " << blocks << "\n";
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
            renderer_.draw_world(frame.build(camera, 1, kDrawnTime * n));
        }
        EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
        gl_->dump_if_requested(std::filesystem::path(path).stem().string());
        const std::vector<Rgb> pixels = gl_->pixels();
        check_against_the_maps_light(pixels, data->bsp(), camera, engine_.palette);
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

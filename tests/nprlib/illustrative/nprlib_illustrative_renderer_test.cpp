// IllustrativeRenderer as a plugin runs it: whole frames of the lifecycle scene (world, brush
// entity, a translated player with its view model, sprite, particles) allocate nothing once
// warm; models are shaded by the style, not the classic drawer; a model's material file, the
// style's ramp setting and the world abstraction reach the pixels; malformed material files and
// ramps are reported with the file's name and the defaults drawn instead; shutdown releases
// every GL object.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "classic/classic_renderer.h"
#include "illustrative/illustrative_renderer.h"
#include "support/nprlib_test_scene.h"
#include "support/nprlib_test_support.h"
#include "support/allocation_counter.h"  // replaces operator new for this executable

namespace nq::npr::test {
namespace {

using illustrative::IllustrativeRenderer;
using ::nq::test::g_allocations;

// The files the test engine serves (path -> bytes); a C callback cannot capture, so they live
// here, filled by each test.
std::map<std::string, std::string>& served_files() {
    static std::map<std::string, std::string> files;
    return files;
}

int serve_file(void*, const char* path, nqr_blob* out) {
    const auto it = served_files().find(path);
    if (it == served_files().end()) return 1;
    out->data = reinterpret_cast<const uint8_t*>(it->second.data());
    out->length = it->second.size();
    return 0;
}

void free_file(void*, nqr_blob*) {}

int differing(const std::vector<Rgb>& a, const std::vector<Rgb>& b) {
    int n = 0;
    for (size_t i = 0; i < a.size(); ++i) n += a[i] != b[i];
    return n;
}

bool logged(const std::string& needle) {
    return std::any_of(captured_log().begin(), captured_log().end(), [&](const std::string& line) {
        return line.find(needle) != std::string::npos;
    });
}

class IllustrativeRendererTest : public GlSuiteTest<IllustrativeRendererTest> {
  protected:
    void SetUp() override {
        GlSuiteTest::SetUp();
        if (HasFatalFailure()) return;
        served_files().clear();
        captured_log().clear();
        engine_.engine.file_read = serve_file;
        engine_.engine.file_free = free_file;
        scene_.build_models();
        scene_.build_frame();
        light(scene_.guy, lights_[0]);
        light(scene_.weapon, lights_[1]);
    }

    // A grey ambient cube and one light above and to the side of the models.
    static void light(nqr_entity& entity, TestLight& lit) {
        entity.light = &lit.light;
        for (auto& face : lit.light.ambient_cube) std::fill_n(face, 3, 0.4f);
        lit.light.num_lights = 1;
        nqr_light_source& source = lit.sources[0];
        source.size = sizeof(nqr_light_source);
        const float position[3] = {100.0f, 30.0f, 120.0f}, colour[3] = {0.9f, 0.8f, 0.7f};
        std::copy_n(position, 3, source.position);
        std::copy_n(colour, 3, source.color);
    }

    void TearDown() override {
        renderer_.shutdown();
        EXPECT_EQ(renderer_.live_gl_objects(), 0);
        served_files().clear();
    }

    // A fresh renderer with the scene registered (material files and settings apply at load).
    void start(const illustrative::IllustrativeSettings& settings = {}) {
        renderer_.shutdown();
        renderer_.settings = settings;
        std::string error;
        ASSERT_TRUE(renderer_.init(&engine_.engine, &error)) << error;
        scene_.register_all(renderer_);
    }

    std::vector<Rgb> frame() {
        renderer_.begin_frame();
        scene_.draw(renderer_, *gl_, 0);
        return gl_->pixels();
    }

    TestEngine engine_;
    IllustrativeRenderer renderer_;
    Scene scene_;
    std::array<TestLight, 2> lights_;  // the guy's and the weapon's
};

TEST_F(IllustrativeRendererTest, SteadyStateFramesDoNotAllocate) {
    start();
    for (int n = 0; n < 14; ++n) {
        renderer_.begin_frame();
        scene_.draw(renderer_, *gl_, n);
    }
    glFinish();
    g_allocations = 0;
    for (int n = 14; n < 28; ++n) {
        renderer_.begin_frame();
        scene_.draw(renderer_, *gl_, n);
    }
    glFinish();
    EXPECT_EQ(g_allocations.load(), 0);
    auto probe = std::make_unique<int>(1);  // the counter does count
    EXPECT_EQ(g_allocations.load(), 1);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(IllustrativeRendererTest, ModelsAreShadedByTheStyleAndTheRestIsClassic) {
    illustrative::IllustrativeSettings plain_world;
    plain_world.abstract_world = false;
    start(plain_world);
    const std::vector<Rgb> styled = frame();
    classic::ClassicRenderer classic;
    std::string error;
    ASSERT_TRUE(classic.init(&engine_.engine, &error)) << error;
    scene_.register_all(classic);
    scene_.draw(classic, *gl_, 0);
    const std::vector<Rgb> reference = gl_->pixels();
    classic.shutdown();
    // The player and its view model differ; with the models left out, nothing does.
    EXPECT_GT(differing(styled, reference), 100);
    scene_.frame.alias.clear();
    const std::vector<Rgb> styled_world = frame();
    ASSERT_TRUE(classic.init(&engine_.engine, &error)) << error;
    scene_.register_all(classic);
    scene_.draw(classic, *gl_, 0);
    EXPECT_EQ(differing(styled_world, gl_->pixels()), 0);
    classic.shutdown();
}

TEST_F(IllustrativeRendererTest, TheWorldAbstractionChangesWorldTexturesAtLoad) {
    illustrative::IllustrativeSettings off;
    off.abstract_world = false;
    scene_.frame.alias.clear();
    start(off);
    const std::vector<Rgb> plain = frame();
    start();  // ill_abstract 1, the default
    EXPECT_GT(differing(plain, frame()), 100);
}

TEST_F(IllustrativeRendererTest, AMaterialFileOverridesTheModelsTerms) {
    start();
    const std::vector<Rgb> defaults = frame();
    served_files()["progs/test.mdl.mat"] =
        "\"VertexLitGeneric\"\n{\n  $phongboost 40 // very shiny\n  $rimlightboost 30\n}\n";
    start();
    EXPECT_GT(differing(defaults, frame()), 30);
    EXPECT_FALSE(logged("progs/test.mdl.mat"));  // a clean file: no warning
}

TEST_F(IllustrativeRendererTest, AMalformedMaterialFileWarnsAndTheDefaultsAreDrawn) {
    start();
    const std::vector<Rgb> defaults = frame();
    served_files()["progs/test.mdl.mat"] = std::string("$phongboost 40\n\x01\x02\xff\xfe", 19);
    start();
    EXPECT_EQ(differing(defaults, frame()), 0);
    EXPECT_TRUE(logged("progs/test.mdl.mat")) << "no warning naming the file";
}

TEST_F(IllustrativeRendererTest, AMissingMaterialRampWarnsAndTheStylesRampIsDrawn) {
    start();
    const std::vector<Rgb> defaults = frame();
    served_files()["progs/test.mdl.mat"] = "$lightwarptexture gfx/nothere.png\n";
    start();
    EXPECT_EQ(differing(defaults, frame()), 0);
    EXPECT_TRUE(logged("gfx/nothere.png"));
}

TEST_F(IllustrativeRendererTest, TheRampSettingSwapsRampsWhileRunningAndABadOneFallsBack) {
    start();
    const std::vector<Rgb> tf2 = frame();
    renderer_.settings.warp_ramp = "cel";
    EXPECT_GT(differing(tf2, frame()), 30);
    // A corrupt PNG ramp: reported, and the TF2 ramp drawn.
    served_files()["gfx/broken.png"] = std::string("\x89PNG\r\n\x1a\n garbage", 16);
    renderer_.settings.warp_ramp = "gfx/broken.png";
    EXPECT_EQ(differing(tf2, frame()), 0);
    EXPECT_TRUE(logged("gfx/broken.png"));
}

TEST_F(IllustrativeRendererTest, AUserRampImageIsRead) {
    start();
    const std::vector<Rgb> tf2 = frame();
    // A 4 x 1 Quake .lmp: width, height (little-endian), then palette indices (greys).
    const uint8_t lmp[] = {4, 0, 0, 0, 1, 0, 0, 0, 10, 60, 120, 200};
    served_files()["gfx/myramp.lmp"] = std::string(reinterpret_cast<const char*>(lmp), sizeof lmp);
    renderer_.settings.warp_ramp = "gfx/myramp.lmp";
    EXPECT_GT(differing(tf2, frame()), 30);
    EXPECT_FALSE(logged("gfx/myramp.lmp"));
}

}  // namespace
}  // namespace nq::npr::test

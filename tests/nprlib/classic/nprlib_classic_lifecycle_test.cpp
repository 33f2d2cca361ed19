// ClassicRenderer's lifetime rules: init failures, model release, every GL object gone after
// shutdown (by its own counters and by asking GL), and no heap allocation in steady-state frames
// (counted by replacing the global operator new in this test binary).
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <memory>
#include <new>

#include "classic/classic_renderer.h"
#include "support/nprlib_test_scene.h"
#include "support/nprlib_test_support.h"
#include "support/allocation_counter.h"

namespace nq::npr::test {
namespace {

using classic::ClassicRenderer;
using ::nq::test::g_allocations;

class ClassicLifecycleTest : public GlSuiteTest<ClassicLifecycleTest> {
  protected:
    void SetUp() override {
        GlSuiteTest::SetUp();
        if (HasFatalFailure()) return;
    }

    TestEngine engine_;
};

TEST_F(ClassicLifecycleTest, InitFailsWithoutAPaletteAndLeavesNothingBehind) {
    ClassicRenderer renderer;
    nqr_engine engine = engine_.engine;
    engine.palette = nullptr;
    captured_log().clear();
    std::string error;
    EXPECT_FALSE(renderer.init(&engine, &error));
    EXPECT_NE(error.find("palette"), std::string::npos) << error;
    EXPECT_FALSE(renderer.initialised());
    EXPECT_EQ(renderer.live_gl_objects(), 0);
    ASSERT_FALSE(captured_log().empty());
    EXPECT_NE(captured_log().back().find("palette"), std::string::npos);

    EXPECT_FALSE(renderer.init(nullptr, &error));  // no engine at all
}

TEST_F(ClassicLifecycleTest, HooksBeforeInitAndWithBadFramesDoNothing) {
    ClassicRenderer renderer;
    TestFrame frame;
    const nqr_frame* f = frame.build(make_camera({0, 0, 0}, {0, 0, 0}), 1);
    renderer.draw_world(f);  // not initialised: ignored
    std::string error;
    ASSERT_TRUE(renderer.init(&engine_.engine, &error)) << error;
    nqr_frame old = *f;
    old.size = 16;  // an older, shorter frame than this build reads
    renderer.draw_world(&old);
    renderer.draw_alias_entities(nullptr);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(ClassicLifecycleTest, ReleasingModelsFreesTheirGpuObjects) {
    ClassicRenderer renderer;
    std::string error;
    ASSERT_TRUE(renderer.init(&engine_.engine, &error)) << error;
    const int baseline = renderer.live_gl_objects();
    Scene scene;
    scene.build_models();
    scene.register_all(renderer);
    EXPECT_EQ(renderer.models().size(), 4u);
    EXPECT_GT(renderer.live_gl_objects(), baseline);

    renderer.release_model(1);  // the world: its brush geometry stays for "*1"
    EXPECT_EQ(renderer.models().brush_geometry_count(), 1u);
    renderer.release_model(2);
    EXPECT_EQ(renderer.models().brush_geometry_count(), 0u);
    renderer.release_model(3);
    renderer.release_model(4);
    renderer.release_model(99);  // unknown: ignored
    EXPECT_EQ(renderer.models().size(), 0u);
    EXPECT_EQ(renderer.live_gl_objects(), baseline);
}

TEST_F(ClassicLifecycleTest, ShutdownLeavesNoLiveGlObjects) {
    ClassicRenderer renderer;
    std::string error;
    ASSERT_TRUE(renderer.init(&engine_.engine, &error)) << error;
    Scene scene;
    scene.build_models();
    scene.register_all(renderer);
    scene.build_frame();
    for (int n = 0; n < 3; ++n) scene.draw(renderer, *gl_, n);
    ASSERT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    const gl::ObjectTracker& objects = renderer.gl_objects();
    EXPECT_GT(objects.created(gl::ObjectKind::texture), 10);
    EXPECT_GT(objects.created(gl::ObjectKind::program), 4);

    renderer.shutdown();
    for (size_t k = 0; k < gl::kObjectKindCount; ++k) {
        const auto kind = static_cast<gl::ObjectKind>(k);
        EXPECT_EQ(objects.live(kind), 0) << gl::object_kind_name(kind);
    }
    // Independently of the counters: GL knows none of the names any more. The test's own
    // framebuffer (one texture) is the only object left.
    int textures = 0, buffers = 0, arrays = 0, programs = 0;
    for (GLuint name = 1; name < 4096; ++name) {
        textures += glIsTexture(name);
        buffers += glIsBuffer(name);
        arrays += glIsVertexArray(name);
        programs += glIsProgram(name);
    }
    EXPECT_EQ(textures, 1);
    EXPECT_EQ(buffers, 0);
    EXPECT_EQ(arrays, 0);
    EXPECT_EQ(programs, 0);
}

TEST_F(ClassicLifecycleTest, SteadyStateFramesDoNotAllocate) {
    ClassicRenderer renderer;
    std::string error;
    ASSERT_TRUE(renderer.init(&engine_.engine, &error)) << error;
    Scene scene;
    scene.build_models();
    scene.register_all(renderer);
    scene.build_frame();
    for (int n = 0; n < 14; ++n) scene.draw(renderer, *gl_, n);  // warm-up: every state seen
    glFinish();

    const int rebuilds_before = renderer.models().find(1)->brush->lightmap_rebuilds();
    const long before = g_allocations.load();
    for (int n = 14; n < 28; ++n) scene.draw(renderer, *gl_, n);
    const long allocated = g_allocations.load() - before;
    glFinish();
    EXPECT_EQ(allocated, 0);
    // Lightmaps were rebuilt and uploaded in those frames (the moving light, the style).
    EXPECT_GT(renderer.models().find(1)->brush->lightmap_rebuilds(), rebuilds_before + 14);

    // The counter does count: one allocation is one.
    const long before_probe = g_allocations.load();
    auto probe = std::make_unique<int>(1);
    EXPECT_EQ(g_allocations.load() - before_probe, 1);

    // The frames really drew (not an empty pass that trivially allocates nothing).
    EXPECT_GT(coverage(gl_->pixels(), {}).count, 5000);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

}  // namespace
}  // namespace nq::npr::test

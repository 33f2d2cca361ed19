// ClassicRenderer's lifetime rules: init failures, model release, every GL object gone after
// shutdown (by its own counters and by asking GL), and no heap allocation in steady-state frames
// (counted by replacing the global operator new in this test binary).
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <memory>
#include <new>

#include "classic/classic_renderer.h"
#include "nprlib_test_support.h"

namespace {

std::atomic<bool> g_counting{false};
std::atomic<long> g_allocations{0};

void* counted_allocation(std::size_t bytes) {
    if (g_counting.load(std::memory_order_relaxed)) g_allocations.fetch_add(1);
    if (void* p = std::malloc(bytes ? bytes : 1)) return p;
    throw std::bad_alloc();
}

}  // namespace

void* operator new(std::size_t bytes) {
    return counted_allocation(bytes);
}
void* operator new[](std::size_t bytes) {
    return counted_allocation(bytes);
}
void* operator new(std::size_t bytes, const std::nothrow_t&) noexcept {
    try {
        return counted_allocation(bytes);
    } catch (...) {
        return nullptr;
    }
}
void* operator new[](std::size_t bytes, const std::nothrow_t&) noexcept {
    try {
        return counted_allocation(bytes);
    } catch (...) {
        return nullptr;
    }
}
void operator delete(void* p) noexcept {
    std::free(p);
}
void operator delete[](void* p) noexcept {
    std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept {
    std::free(p);
}

namespace nq::npr::test {
namespace {

using classic::ClassicRenderer;

class ClassicLifecycleTest : public GlSuiteTest<ClassicLifecycleTest> {
  protected:
    void SetUp() override {
        GlSuiteTest::SetUp();
        if (HasFatalFailure()) return;
    }

    TestEngine engine_;
};

// Every kind of model and drawing at once: world (lit, fullbright, sky, liquid, animated),
// a brush entity, a translated player, a sprite, particles and a moving dynamic light.
struct Scene {
    BrushBuilder brush;
    AliasBuilder player;
    SpriteBuilder sprite;
    nqr_entity door{}, guy{}, weapon{}, flare{};
    TestFrame frame;

    void build_models() {
        const auto grey =
            make_image(16, 16, [](int x, int) { return x < 4 ? colour::kFullbrightGreen : 150; });
        const int floor = brush.add_texture("floor", 16, 16, grey);
        const int anim0 = brush.add_texture(
            "+0anim", 16, 16, make_image(16, 16, [](int, int) { return colour::kRed; }));
        const int anim1 = brush.add_texture(
            "+1anim", 16, 16, make_image(16, 16, [](int, int) { return colour::kBlue; }));
        brush.set_animation(anim0, {anim0, anim1});
        brush.set_animation(anim1, {anim0, anim1});
        const int sky = brush.add_texture(
            "sky1", 256, 128,
            make_image(
                256, 128,
                [](int x, int) { return x >= 128 ? colour::kBlue : (x % 16 < 8 ? 0 : 150); }),
            NQR_TEXTURE_SKY);
        const int water = brush.add_texture(
            "*water", 64, 64,
            make_image(64, 64,
                       [](int x, int) { return x % 16 < 8 ? colour::kTeal : colour::kRed; }),
            NQR_TEXTURE_LIQUID);
        brush.add_floor({0, 0, 64, 64, 0, floor});
        brush.add_floor({64, 0, 128, 64, 0, anim0});
        BrushBuilder::Quad sky_quad{0, 64, 64, 128, 0, sky};
        sky_quad.flags = NQR_SURFACE_SKY;
        brush.add_floor(sky_quad);
        BrushBuilder::Quad water_quad{64, 64, 128, 128, 0, water};
        water_quad.flags = NQR_SURFACE_LIQUID;
        brush.add_floor(water_quad);
        brush.add_floor({0, 0, 16, 16, 0, floor});  // surface 4: submodel *1
        brush.build();

        player.add_box_pose({0, 0, 0}, {16, 16, 16});
        player.add_box_pose({0, 8, 0}, {16, 24, 16});
        player.origin = glm::vec3(-8.0f);
        player.skin.assign(64, colour::kShirtBase + 3);
        player.build();

        sprite.images.push_back({8, 8, -4, 4, make_image(8, 8, [](int x, int) {
                                     return x < 4 ? colour::kOrange : colour::kTransparent;
                                 })});
    }

    void register_all(ClassicRenderer& renderer) {
        nqr_model world = brush.model(1, 0, 4);
        nqr_model submodel = brush.model(2, 4, 1, "*1");
        nqr_model guy_model = player.model(3);
        nqr_model flare_model = sprite.model(4);
        for (const nqr_model* m : {&world, &submodel, &guy_model, &flare_model}) {
            renderer.register_model(m);
        }
    }

    void build_frame() {
        door = make_entity(2, glm::translate(glm::mat4(1.0f), {40.0f, 40.0f, 4.0f}));
        guy = make_entity(3, glm::translate(glm::mat4(1.0f), {64.0f, 64.0f, 16.0f}));
        guy.has_translation = 1;
        guy.top_color = 4;
        guy.bottom_color = 12;
        guy.pose1 = 1;
        guy.lerp = 0.3f;
        weapon = make_entity(3, glm::translate(glm::mat4(1.0f), {80.0f, 64.0f, 40.0f}));
        weapon.flags = NQR_ENTITY_VIEWMODEL;
        flare = make_entity(4, glm::translate(glm::mat4(1.0f), {30.0f, 90.0f, 10.0f}));
        frame.brush = {&door};
        frame.alias = {&guy, &weapon};
        frame.sprite = {&flare};
        frame.visible = {0, 1, 2, 3};
        frame.use_visible_list = true;
        for (int i = 0; i < 100; ++i) {
            frame.particles.push_back(
                make_particle({20.0f + i % 10, 20.0f + i / 10, 8.0f}, colour::kRed + i % 3));
        }
        frame.dlights.push_back(make_dlight({32, 32, 16}, 120));
    }

    // One whole frame; the light moves and a style flickers so lightmaps rebuild every time.
    void draw(ClassicRenderer& renderer, const GlTestContext& gl, int n) {
        frame.dlights[0].origin[0] = 20.0f + static_cast<float>(n % 7) * 10.0f;
        frame.lightstyles[0] = (n % 2) ? 1.0f : 0.6f;
        const nqr_camera camera = make_camera({64.0f, 64.0f, 80.0f}, {90.0f, 0.0f, 0.0f});
        gl.clear();
        const nqr_frame* f = frame.build(camera, 1, 0.1 * n);
        renderer.draw_world(f);
        renderer.draw_brush_entities(f);
        renderer.draw_alias_entities(f);
        renderer.draw_sprite_entities(f);
        renderer.draw_particles(f);
    }
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
    g_allocations = 0;
    g_counting = true;
    for (int n = 14; n < 28; ++n) scene.draw(renderer, *gl_, n);
    g_counting = false;
    glFinish();
    EXPECT_EQ(g_allocations.load(), 0);
    // Lightmaps were rebuilt and uploaded in those frames (the moving light, the style).
    EXPECT_GT(renderer.models().find(1)->brush->lightmap_rebuilds(), rebuilds_before + 14);

    // The counter does count: one allocation while counting is one.
    g_counting = true;
    auto probe = std::make_unique<int>(1);
    g_counting = false;
    EXPECT_EQ(g_allocations.load(), 1);

    // The frames really drew (not an empty pass that trivially allocates nothing).
    EXPECT_GT(coverage(gl_->pixels(), {}).count, 5000);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

}  // namespace
}  // namespace nq::npr::test

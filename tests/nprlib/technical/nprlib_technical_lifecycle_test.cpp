// TechnicalRenderer in steady state: whole frames of the lifecycle scene (world, brush entity,
// a translated player with its view model, sprite, particles) with every technical effect on
// (Gooch faces, alias and brush edges, umbra + penumbra shadows on a floor the engine's trace
// finds) allocate nothing on the heap once warm (counted by replacing the global operator new
// in this test binary), and all of them really drew.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include <glm/gtc/type_ptr.hpp>

#include "support/nprlib_test_scene.h"
#include "support/nprlib_test_support.h"
#include "support/allocation_counter.h"  // replaces operator new for this executable
#include "technical/technical_renderer.h"

namespace nq::npr::test {
namespace {

using ::nq::test::g_allocations;
using technical::TechnicalRenderer;

const glm::vec3 kEye(64.0f, 64.0f, 80.0f);  // Scene::draw's camera

// The scene's floor, z = 0, straight under any start point.
void floor_trace(void*, const float start[3], const float end[3], nqr_trace* out) {
    const uint32_t size = out->size;
    *out = nqr_trace{};
    out->size = size;
    out->fraction = 1.0f;
    if (start[2] <= 0.0f || end[2] > 0.0f) return;
    out->fraction = start[2] / (start[2] - end[2]);
    for (int i = 0; i < 3; ++i) out->end[i] = start[i] + (end[i] - start[i]) * out->fraction;
    out->plane_normal[2] = 1.0f;
}

class TechnicalLifecycleTest : public GlSuiteTest<TechnicalLifecycleTest> {
  protected:
    void SetUp() override {
        GlSuiteTest::SetUp();
        if (HasFatalFailure()) return;
        engine_.engine.trace = floor_trace;
        std::string error;
        ASSERT_TRUE(renderer_.init(&engine_.engine, &error)) << error;
        scene_.build_models();
        scene_.register_all(renderer_);
        scene_.build_frame();
        for (nqr_entity* entity : {&scene_.guy, &scene_.weapon}) {
            const glm::mat4 to_model = glm::inverse(glm::make_mat4(entity->model_matrix));
            const glm::vec3 eye(to_model * glm::vec4(kEye, 1.0f));
            std::copy_n(glm::value_ptr(eye), 3, entity->eye_model);
            const glm::vec3 light = glm::normalize(glm::vec3(0.3f, 0.2f, 1.0f));
            std::copy_n(glm::value_ptr(light), 3, light_.direction);
            entity->light = &light_;
        }
    }

    std::vector<Rgb> frame_with(bool edges, bool shadows) {
        renderer_.settings.edges.silhouettes = renderer_.settings.edges.creases = edges;
        renderer_.settings.edges.world_edges = edges;
        renderer_.settings.shadows.enabled = shadows;
        scene_.draw(renderer_, *gl_, 0);
        return gl_->pixels();
    }

    TestEngine engine_;
    TechnicalRenderer renderer_;
    Scene scene_;
    nqr_entity_light light_ = make_light();  // both models' light
};

TEST_F(TechnicalLifecycleTest, SteadyStateFramesDoNotAllocate) {
    for (int n = 0; n < 14; ++n) scene_.draw(renderer_, *gl_, n);  // warm-up: every state seen
    glFinish();
    g_allocations = 0;
    for (int n = 14; n < 28; ++n) scene_.draw(renderer_, *gl_, n);
    glFinish();
    EXPECT_EQ(g_allocations.load(), 0);
    // The counter does count.
    auto probe = std::make_unique<int>(1);
    EXPECT_EQ(g_allocations.load(), 1);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(TechnicalLifecycleTest, TheCountedFramesDrawEdgesAndShadows) {
    const std::vector<Rgb> plain = frame_with(false, false);
    const std::vector<Rgb> edges = frame_with(true, false);
    const std::vector<Rgb> shadows = frame_with(false, true);
    const auto differing = [](const std::vector<Rgb>& a, const std::vector<Rgb>& b) {
        int n = 0;
        for (size_t i = 0; i < a.size(); ++i) n += a[i] != b[i];
        return n;
    };
    EXPECT_GT(differing(plain, edges), 30);
    EXPECT_GT(differing(plain, shadows), 30);
}

}  // namespace
}  // namespace nq::npr::test

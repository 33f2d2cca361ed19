// The per-frame client work allocates nothing in steady state: preparing the frame
// (interpolation, effects, particles, lights, beams), the view, the visible-entity list and
// the export to the renderer ABI. Counted by replacing the global operator new in this test
// binary. (Reading demo blocks is counted with the engine's demo path in
// engine_demo_alloc_test.)
#include <gtest/gtest.h>

#include <vector>

#include "client/demo_player.h"
#include "client/nqr_export.h"
#include "client/view.h"
#include "client/visible_entities.h"
#include "client_test_fixture.h"
#include "support/allocation_counter.h"

namespace nq {
namespace {

using ::nq::test::g_allocations;

struct FrameAllocations {
    size_t frames = 0;
    size_t steady_allocations = 0;  // after the warm-up
    size_t max_visible = 0;
    size_t max_particles = 0;
};

FrameAllocations play_counting(const std::string& file, DemoMode mode, size_t warmup) {
    auto player = DemoPlayer::open(test::load_lq1(file), file, mode);
    if (!player) throw std::runtime_error(player.error().to_string());
    ClientState client;
    VisibleEntityList visible(4096);
    ViewState view_state;
    std::vector<nqr_entity> entities(4096);
    std::vector<nqr_particle> particles(kDefaultParticleCapacity);
    std::vector<nqr_dlight> lights(kMaxDynamicLights);
    uint32_t generation = 0;
    FrameAllocations out;
    while (player->read_frame(client, 1.0 / 72) == FrameStatus::Playing) {
        if (client.generation() != generation) {  // a new map: the engine loads models
            generation = client.generation();
            client.set_model_info(test::load_model_info(client.model_names()));
        }
        const size_t before = g_allocations.load();
        client.prepare_frame(player->lerp_mode());
        const ViewResult view = compute_view(client, view_state);
        collect_visible_entities(client, view, visible);
        for (size_t i = 0; i < visible.size(); ++i) {
            export_entity(visible.entities()[i],
                          static_cast<nqr_model_id>(visible.entities()[i].model), entities[i]);
        }
        export_particles(client.particles().particles(), particles);
        export_dynamic_lights(client.dynamic_lights(), client.time(), lights);
        const size_t allocated = g_allocations.load() - before;
        if (out.frames++ >= warmup) out.steady_allocations += allocated;
        out.max_visible = std::max(out.max_visible, visible.size());
        out.max_particles = std::max(out.max_particles, client.particles().size());
    }
    EXPECT_FALSE(player->error().has_value());
    return out;
}

TEST(ClientAllocations, CounterSeesAllocations) {
    // Direct calls: the optimiser may drop a new-expression whose memory is never used, but
    // not a call of the allocation function itself.
    const size_t before = g_allocations.load();
    void* one = ::operator new(64);
    void* many = ::operator new[](64);
    ::operator delete[](many);
    ::operator delete(one);
    EXPECT_EQ(g_allocations.load() - before, 2u);
}

TEST(ClientAllocations, TimedemoFramesDoNotAllocate) {
    for (const char* file : {"demo.dem", "demo2.dem"}) {
        FrameAllocations a = play_counting(file, DemoMode::TimeDemo, 10);
        EXPECT_GT(a.frames, 1000u) << file;
        EXPECT_EQ(a.steady_allocations, 0u) << file;
        EXPECT_GT(a.max_visible, 10u) << file;
    }
}

TEST(ClientAllocations, PlaybackFramesDoNotAllocate) {
    FrameAllocations a = play_counting("demo2.dem", DemoMode::Playback, 10);
    EXPECT_GT(a.frames, 1000u);
    EXPECT_EQ(a.steady_allocations, 0u);
    EXPECT_GT(a.max_particles, 1000u);  // explosions and teleports happened
}

}  // namespace
}  // namespace nq

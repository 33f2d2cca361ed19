// The engine's per-frame demo path allocates nothing in steady state. Driven in-process the way
// Engine::frame drives it, without a window: DemoSession::frame (reading the due blocks,
// decoding them, applying them to the client, preparing the frame, passing on console text),
// the view, SceneBuilder::build (culling, entities, lighting), and the screen tint and status
// bar quads the engine draws over the view (view_blend, build_hud). Counted by replacing the
// global operator new in this test binary.
//
// Frames that may allocate, and are left out: the first frames of each level (warm-up: the
// level loads, vectors grow to the level's needs) and frames whose messages carry text for
// the console (print, centerprint, stufftext: a string that does not fit a std::string's
// inline storage is allocated; such frames are rare).
#include <gtest/gtest.h>

#include <string_view>

#include "app/sessions/demo_session.h"
#include "app/frame/scene_builder.h"
#include "client/view_blend.h"
#include "support/engine_demo_replay.h"
#include "hud/hud_scene.h"
#include "support/hud_test_support.h"
#include "support/allocation_counter.h"

namespace nq {
namespace {

using ::nq::test::g_allocations;

constexpr size_t kWarmupFrames = 10;  // after the start and after each level load

struct PauseWindow {
    uint64_t at_demo_frame = 0;  // pause once the demo has played this many frames
    size_t held_frames = 0;      // for this many host frames
};

struct AllocationReport {
    size_t host_frames = 0;
    size_t steady_frames = 0;  // checked: past the warm-up, no level load, no console text
    size_t text_frames = 0;    // left out for their console text
    size_t level_loads = 0;
    size_t level_restarts = 0;  // the same map again: the level kept
    size_t allocating_frames = 0;
    long allocations = 0;
    std::string first_allocating;  // "host frame N (demo frame M): K allocations"
    size_t paused_frames = 0;
    bool pause_held_demo = true;  // no demo frame was played while paused
    size_t max_visible_surfaces = 0;
    size_t max_entities = 0;
    size_t max_hud_quads = 0;        // status bar, inventory and crosshair quads of one frame
    float max_tint = 0;              // the strongest screen tint's alpha
    bool played_to_the_end = false;  // the demo ended by itself, without an error
    uint64_t demo_frames = 0;        // frames the demo played
};

int contents_at(void* user, const Vec3& p) {
    const Bsp* bsp = static_cast<const Bsp*>(user);
    return bsp ? point_contents(*bsp, 0, {p[0], p[1], p[2]}) : 0;
}

class CountingDemoRun {
  public:
    explicit CountingDemoRun(const Vfs& vfs) : session_(&vfs, callbacks()) {
        hud_frame_.settings.crosshair = true;  // all of it: bars, inventory, crosshair
        hud_batch_.set_flush([this](std::span<const QuadVertex> v) { hud_quads_ += v.size() / 4; });
    }

    AllocationReport play(const std::string& file, DemoMode mode, double frame_time,
                          PauseWindow pause = {}) {
        std::string why = session_.start(file, mode);
        if (!why.empty()) throw std::runtime_error(why);
        size_t warm_until = kWarmupFrames;
        size_t resume_at = 0;
        while (true) {
            if (pause.held_frames > 0 && !session_.paused() && resume_at == 0 &&
                session_.player()->frames() >= pause.at_demo_frame) {
                session_.set_paused(true);
                resume_at = report_.host_frames + pause.held_frames;
            } else if (session_.paused() && report_.host_frames >= resume_at) {
                session_.set_paused(false);
            }
            if (!frame(frame_time, warm_until)) break;
        }
        const DemoPlayer& player = *session_.player();
        report_.played_to_the_end = player.ended() && !player.error();
        report_.demo_frames = player.frames();
        return report_;
    }

  private:
    DemoSessionCallbacks callbacks() {
        DemoSessionCallbacks c;
        auto text = [this](std::string_view) { text_this_frame_ = true; };
        c.print = text;
        c.center_print = text;
        c.stuff_text = text;
        c.level_unloading = [] {};
        c.level_loaded = [this](Level& level) {
            scene_.bind_level(level);
            loaded_this_frame_ = true;
        };
        c.level_restarted = [this](Level&) {
            ++report_.level_restarts;
            loaded_this_frame_ = true;
        };
        return c;
    }

    // One host frame; false when the demo ended in it.
    bool frame(double frame_time, size_t& warm_until) {
        text_this_frame_ = loaded_this_frame_ = false;
        const bool paused = session_.paused();
        const uint64_t demo_frames = session_.player()->frames();
        const long before = g_allocations.load();
        const size_t restarts_before = report_.level_restarts;
        if (session_.frame(frame_time) == FrameStatus::Ended) return false;
        draw_scene(frame_time);
        const long allocated = g_allocations.load() - before;

        const size_t n = report_.host_frames++;
        if (paused) {
            ++report_.paused_frames;
            report_.pause_held_demo &= session_.player()->frames() == demo_frames;
        }
        if (loaded_this_frame_) {
            report_.level_loads += report_.level_restarts == restarts_before ? 1 : 0;
            warm_until = n + kWarmupFrames;
        }
        if (n < warm_until || loaded_this_frame_) return true;
        if (text_this_frame_) {
            ++report_.text_frames;
            return true;
        }
        ++report_.steady_frames;
        if (allocated > 0) {
            if (report_.allocating_frames++ == 0) {
                report_.first_allocating = "host frame " + std::to_string(n) + " (demo frame " +
                                           std::to_string(session_.player()->frames()) +
                                           "): " + std::to_string(allocated) + " allocations";
            }
            report_.allocations += allocated;
        }
        return true;
    }

    // What Engine::render_demo does before handing the frame to the renderer.
    void draw_scene(double frame_time) {
        if (!session_.level_ready()) return;
        Level& level = session_.level();
        ViewSettings settings;
        settings.contents_at = &contents_at;
        settings.contents_user = const_cast<Bsp*>(level.world_bsp());
        const ViewResult view = compute_view(session_.client(), view_state_, settings);
        CameraSetup camera;
        camera.origin = {view.origin[0], view.origin[1], view.origin[2]};
        camera.angles = {view.angles[0], view.angles[1], view.angles[2]};
        camera.viewport[2] = 320;
        camera.viewport[3] = 240;
        real_time_ += frame_time;
        const nqr_frame& f = scene_.build(level, session_.client(), view, camera, real_time_,
                                          static_cast<float>(frame_time));
        report_.max_visible_surfaces =
            std::max<size_t>(report_.max_visible_surfaces, f.num_visible_surfaces);
        report_.max_entities =
            std::max<size_t>(report_.max_entities, f.num_alias_entities + f.num_brush_entities);

        // What Engine::render_demo draws after the renderer (as quads; the GL part is fixed).
        report_.max_tint =
            std::max(report_.max_tint, view_blend(session_.client(), view.eye_contents).a);
        hud_quads_ = 0;
        hud_frame_.real_time = real_time_;
        build_hud(session_.client(), hud_frame_, hud_.pictures, hud_batch_);
        hud_batch_.flush();
        report_.max_hud_quads = std::max(report_.max_hud_quads, hud_quads_);
    }

    SceneBuilder scene_;
    test::HudTestData hud_;
    HudFrame hud_frame_ = test::hud_frame(320, 240);
    QuadBatch hud_batch_{256};
    size_t hud_quads_ = 0;
    DemoSession session_;
    ViewState view_state_;
    double real_time_ = 0;
    bool text_this_frame_ = false;
    bool loaded_this_frame_ = false;
    AllocationReport report_;
};

TEST(EngineDemoAllocations, CounterSeesAllocations) {
    const long before = g_allocations.load();
    auto* text = new std::string(100, 'x');
    delete text;
    EXPECT_GE(g_allocations.load() - before, 2);
}

TEST(EngineDemoAllocations, WholeTimedemoOfDemoAllocatesNothingPerFrame) {
    Vfs vfs = test::mount_lq1();
    CountingDemoRun run(vfs);
    AllocationReport r = run.play("demo", DemoMode::TimeDemo, 0.01);
    EXPECT_EQ(r.allocating_frames, 0u) << r.first_allocating;
    EXPECT_EQ(r.allocations, 0);
    // The run checked what it claims: the whole demo, a level with surfaces and entities.
    EXPECT_TRUE(r.played_to_the_end);
    EXPECT_EQ(r.host_frames, r.demo_frames);  // timedemo: one demo frame per host frame
    EXPECT_GE(r.level_loads, 1u);
    EXPECT_GT(r.steady_frames, r.host_frames * 9 / 10);
    EXPECT_GT(r.max_visible_surfaces, 100u);
    EXPECT_GT(r.max_entities, 10u);
    EXPECT_GT(r.max_hud_quads, 20u);  // the status bar was built every frame
}

TEST(EngineDemoAllocations, PlaybackOfDemo2WithAPauseAllocatesNothingPerFrame) {
    Vfs vfs = test::mount_lq1();
    CountingDemoRun run(vfs);
    AllocationReport r =
        run.play("demo2", DemoMode::Playback, 1.0 / 72, PauseWindow{/*at*/ 400, /*held*/ 30});
    EXPECT_EQ(r.allocating_frames, 0u) << r.first_allocating;
    EXPECT_EQ(r.allocations, 0);
    EXPECT_TRUE(r.played_to_the_end);
    // demo2 restarts its map (demo frame 1437): the loaded level and its models serve again
    // (a reload took ~200 ms, the run's slowest frame).
    EXPECT_EQ(r.level_loads, 1u);
    EXPECT_EQ(r.level_restarts, 1u);
    EXPECT_GT(r.steady_frames, 1000u);
    EXPECT_EQ(r.paused_frames, 30u);
    EXPECT_EQ(r.host_frames, r.demo_frames + 30);
    EXPECT_TRUE(r.pause_held_demo);
    EXPECT_GT(r.max_hud_quads, 20u);
    EXPECT_GT(r.max_tint, 0.0f) << "demo2 has damage or pickup flashes";
}

}  // namespace
}  // namespace nq

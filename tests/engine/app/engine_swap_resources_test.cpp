// Fifty renderer swaps leave no GL objects and no heap behind: the engine's plugin pieces
// (HostServices, PluginHost, RenderDispatch) run in-process on an offscreen window with the
// showroom's models registered, swapping between the real classic and null plugins and drawing
// frames in between. What the driver holds is counted from outside the plugins: every GL name
// that is a live object of each kind.
#include <epoxy/gl.h>
#include <gtest/gtest.h>
#include <malloc.h>

#include <array>
#include <memory>
#include <optional>

#include "app/frame/host_services.h"
#include "app/frame/render_dispatch.h"
#include "app/frame/scene_builder.h"
#include "app/frame/showroom.h"
#include "host/host_core.h"
#include "plugin/plugin_host.h"
#include "support/build_paths.h"
#include "support/video_test_support.h"

#if defined(__SANITIZE_ADDRESS__)
#define NQ_TEST_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define NQ_TEST_ASAN 1
#endif
#endif
#ifdef NQ_TEST_ASAN
// From the sanitizer runtime's public interface (sanitizer/allocator_interface.h, which GCC
// does not install everywhere).
extern "C" size_t __sanitizer_get_current_allocated_bytes();
#endif

namespace nq {
namespace {

constexpr int kWidth = 160, kHeight = 120;

// Bytes the program has allocated and not freed (ASan's allocator keeps its own books).
size_t heap_in_use() {
#ifdef NQ_TEST_ASAN
    return __sanitizer_get_current_allocated_bytes();
#else
    return mallinfo2().uordblks;
#endif
}

// Live GL objects of each kind among names 1..kMaxName (the classic plugin creates a few
// dozen per load; fifty loads stay far below this bound even without name reuse).
struct GlObjectCounts {
    std::array<int, 6> live{};  // textures, buffers, vertex arrays, framebuffers, programs, shaders
    bool operator==(const GlObjectCounts&) const = default;
};

std::ostream& operator<<(std::ostream& os, const GlObjectCounts& c) {
    return os << "textures " << c.live[0] << ", buffers " << c.live[1] << ", vertex arrays "
              << c.live[2] << ", framebuffers " << c.live[3] << ", programs " << c.live[4]
              << ", shaders " << c.live[5];
}

GlObjectCounts live_gl_objects() {
    constexpr GLuint kMaxName = 20000;
    GlObjectCounts c;
    for (GLuint n = 1; n <= kMaxName; ++n) {
        c.live[0] += glIsTexture(n);
        c.live[1] += glIsBuffer(n);
        c.live[2] += glIsVertexArray(n);
        c.live[3] += glIsFramebuffer(n);
        c.live[4] += glIsProgram(n);
        c.live[5] += glIsShader(n);
    }
    return c;
}

// The engine's renderer side without the engine: services, plugin host, dispatch, showroom.
class SwapRig {
  public:
    explicit SwapRig(VideoWindow& window) : window_(window) {
        HostServicesWiring wiring;
        wiring.host = &host_;
        wiring.log = [](int, std::string_view) {};
        wiring.trace = [](const float*, const float*, nqr_trace*) {};
        wiring.gl_proc_address = &VideoWindow::gl_proc_address;
        services_ = std::make_unique<HostServices>(std::move(wiring));
        auto palette = Showroom::builtin_palette();
        uint8_t rgb[768];
        std::copy(palette.begin(), palette.end(), rgb);
        services_->set_palette(rgb);
        plugins_ = std::make_unique<PluginHost>(*services_, test::plugin_dir());
        dispatch_ = std::make_unique<RenderDispatch>(*plugins_, nullptr);
        showroom_.assign_ids(1);
        for (const nqr_model* m : showroom_.models()) dispatch_->register_model(m);
    }
    ~SwapRig() {
        dispatch_->clear_models();
        dispatch_.reset();
        plugins_.reset();
    }

    std::string load(const std::string& name) { return dispatch_->load_plugin(name); }

    void draw_frame() {
        time_ += 1.0 / 60;
        glViewport(0, 0, kWidth, kHeight);
        glClearColor(0, 0, 0, 1);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        CameraSetup camera = Showroom::default_camera(kWidth, kHeight);
        dispatch_->draw(showroom_.build(scene_, camera, time_, time_, 1.0f / 60));
        window_.swap();
    }

    bool defaults_active() const { return dispatch_->defaults_active(); }

  private:
    VideoWindow& window_;
    HostCore host_;
    std::unique_ptr<HostServices> services_;
    std::unique_ptr<PluginHost> plugins_;
    std::unique_ptr<RenderDispatch> dispatch_;
    Showroom showroom_;
    SceneBuilder scene_;
    double time_ = 0;
};

TEST(EngineSwapResources, FiftySwapsLeaveNoGlObjectsAndNoHeapBehind) {
    auto window = test::make_offscreen_window(kWidth, kHeight);
    ASSERT_TRUE(window) << window.error().message;
    const GlObjectCounts before_any = live_gl_objects();

    struct Snapshot {
        GlObjectCounts gl;
        size_t heap;
    };
    std::optional<Snapshot> early;
    {
        SwapRig rig(*window);
        const char* names[] = {"classic", "null"};
        for (int swap = 0; swap < 50; ++swap) {
            ASSERT_EQ(rig.load(names[swap % 2]), "") << "swap " << swap;
            EXPECT_FALSE(rig.defaults_active()) << "both plugins draw everything themselves";
            rig.draw_frame();
            rig.draw_frame();
            // The same plugin state (classic active) after 10 and after 50 swaps: warm-up
            // allocations (driver caches, first-use tables) are done by the first mark.
            if (swap == 10) early = Snapshot{live_gl_objects(), heap_in_use()};
        }
        ASSERT_EQ(rig.load("classic"), "");
        rig.draw_frame();
        ASSERT_TRUE(early);
        Snapshot late{live_gl_objects(), heap_in_use()};
        EXPECT_EQ(late.gl, early->gl)
            << "GL objects after 10 swaps: " << early->gl << "\nafter 50: " << late.gl;
        // llvmpipe allocates lazily and not deterministically (shader variants, rasteriser
        // threads' bins), so some heap noise is the driver's: allow 1 MiB over 40 swaps. A leak
        // of our own is caught exactly by LeakSanitizer in the asan suite (the binary 50-swap
        // test), and the GL object count above is exact.
        EXPECT_LE(late.heap, early->heap + 1024 * 1024)
            << "the heap grew by " << (late.heap - early->heap) << " bytes in 40 swaps";
    }
    // With the last plugin shut down, the driver holds what it held before any plugin.
    EXPECT_EQ(live_gl_objects(), before_any);
}

}  // namespace
}  // namespace nq

// The engine shell's parts on their own, on SDL's offscreen driver: the Screen (the window the
// command line asks for, the gamma pass on real pixels, vid_restart's locked and fixed-mode
// answers, the vid_* cvars' defaults), the FrameClock (frame durations, the one start-up
// report) and the FrameRenderer (the showroom drawn by a real plugin, a failed swap keeping
// the current plugin, models gone with the showroom), and the Overlay (which keys are the
// menu's, ESCAPE over the console, the menu drawn over the frame).
#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <set>
#include <thread>

#include "app/frame/frame_renderer.h"
#include "app/sessions/demo_session.h"
#include "app/shell/frame_clock.h"
#include "app/shell/game_data.h"
#include "app/shell/overlay.h"
#include "app/shell/screen.h"
#include "fs/vfs.h"
#include "support/build_paths.h"
#include "support/test_data.h"
#include "video/frame_trace.h"
#include "video/gpu_pass_timers.h"

namespace nq {
namespace {

// Above the vid_width/vid_height minimums (320x200), so the cvars can hold the mode.
constexpr int kWidth = 400;
constexpr int kHeight = 300;

std::vector<uint8_t> read_screen(int width, int height) {
    std::vector<uint8_t> rgba(size_t(width) * height * 4);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    return rgba;
}

class ShellTest : public ::testing::Test {
  protected:
    void SetUp() override {
        setenv("SDL_VIDEODRIVER", "offscreen", 1);
        options_.width = kWidth;
        options_.height = kHeight;
        auto screen = Screen::open(
            options_, [this](std::string_view t) { output_ += std::string(t) + "\n"; });
        ASSERT_TRUE(screen) << screen.error().message;
        screen_ = std::move(screen.value());
    }

    LaunchOptions options_;
    std::unique_ptr<Screen> screen_;
    HostCore host_;
    std::string output_;
};

TEST_F(ShellTest, TheWindowHasTheCommandLinesSizeAndNamesItsRenderer) {
    EXPECT_EQ(screen_->width(), kWidth);
    EXPECT_EQ(screen_->height(), kHeight);
    EXPECT_NE(output_.find("GL_RENDERER: " + screen_->gl_info().renderer), std::string::npos)
        << output_;
}

TEST_F(ShellTest, GammaRaisesEachChannelToItsPower) {
    glViewport(0, 0, kWidth, kHeight);
    glClearColor(0.25f, 0.25f, 0.25f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    screen_->apply_levels({1.0f, 1.0f});  // costs nothing, changes nothing
    EXPECT_NEAR(read_screen(kWidth, kHeight)[0], 64, 1);
    screen_->apply_levels({0.5f, 1.0f});
    const std::vector<uint8_t> pixels = read_screen(kWidth, kHeight);
    const double expected = std::pow(64.0 / 255.0, 0.5) * 255.0;  // 0.25^0.5 = 0.5
    for (size_t i = 0; i < pixels.size(); i += 4 * 997) {
        EXPECT_NEAR(pixels[i], expected, 2.0) << "pixel " << i / 4;
    }
}

// QuakeSpasm's `contrast` (LibreQuake's default.cfg sets it): each channel times contrast,
// saturating at white, before gamma.
TEST_F(ShellTest, ContrastScalesEachChannelBeforeGammaAndSaturates) {
    glViewport(0, 0, kWidth, kHeight);
    glClearColor(0.25f, 0.6f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    const std::vector<uint8_t> before = read_screen(kWidth, kHeight);
    screen_->apply_levels({0.8f, 2.0f});
    const std::vector<uint8_t> after = read_screen(kWidth, kHeight);
    for (int c = 0; c < 3; ++c) {
        const double scaled = std::min(1.0, before[c] / 255.0 * 2.0);
        EXPECT_NEAR(after[c], std::pow(scaled, 0.8) * 255.0, 2.0) << "channel " << c;
    }
    EXPECT_EQ(after[1], 255) << "0.6 x 2 saturates";
    EXPECT_EQ(after[kWidth * 4 * (kHeight / 2) + 4 * (kWidth / 3)], after[0]) << "every pixel";
}

TEST_F(ShellTest, VideoCvarsStartAtTheOpenModeAndACommandLineSizeLocksIt) {
    screen_->register_commands(host_, [] {});
    EXPECT_EQ(host_.cvars().find("vid_width")->integer(), kWidth);
    EXPECT_EQ(host_.cvars().find("vid_height")->integer(), kHeight);
    EXPECT_EQ(host_.cvars().find("vid_fullscreen")->integer(), 0);
    host_.set_print([this](std::string_view t) { output_ += std::string(t) + "\n"; });
    host_.commands().add_text("vid_width 640\nvid_restart\n");
    host_.commands().execute();
    EXPECT_NE(output_.find("-width/-height/-window/-fullscreen keep the mode"), std::string::npos)
        << output_;
    EXPECT_EQ(screen_->width(), kWidth);
}

TEST(ShellScreen, WithoutACommandLineSizeTheOffscreenDriverKeepsItsModeAndSaysSo) {
    setenv("SDL_VIDEODRIVER", "offscreen", 1);
    LaunchOptions options;
    std::string output;
    auto screen =
        Screen::open(options, [&](std::string_view t) { output += std::string(t) + "\n"; });
    ASSERT_TRUE(screen) << screen.error().message;
    EXPECT_EQ((*screen)->width(), 640);
    EXPECT_EQ((*screen)->height(), 480);
    HostCore host;
    int resized = 0;
    (*screen)->register_commands(host, [&] { ++resized; });
    host.commands().add_text("vid_width 800\nvid_height 600\nvid_restart\n");
    host.commands().execute();
    EXPECT_NE(output.find("vid_restart: this video driver cannot change the mode"),
              std::string::npos)
        << output;
    EXPECT_EQ(resized, 0);
    EXPECT_EQ((*screen)->width(), 640);
}

TEST(ShellClock, FramesLastFromOneBeginToTheNextAndStartUpIsReportedOnce) {
    FrameClock clock;
    const double t0 = FrameClock::now();
    clock.begin_frame(t0);
    EXPECT_NEAR(clock.begin_frame(t0 + 0.25), 0.25, 1e-9);
    EXPECT_NEAR(clock.begin_frame(t0 + 0.30), 0.05, 1e-9);
    EXPECT_GE(clock.since_start(t0 + 1.0), 1.0);
    std::optional<double> startup = clock.first_frame_done();
    ASSERT_TRUE(startup);
    EXPECT_GE(*startup, 0.0);
    EXPECT_FALSE(clock.first_frame_done()) << "reported once";
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    clock.restart_frames();
    EXPECT_LT(clock.begin_frame(FrameClock::now()), 0.015) << "start-up time is not a frame";
}

class FrameRendererTest : public ShellTest {
  protected:
    void SetUp() override {
        ShellTest::SetUp();
        if (HasFatalFailure()) return;
        timers_.init(true);
        FrameRendererContext context;
        context.host = &host_;
        context.game_data = &game_data_;  // no game data: the showroom's own palette
        context.gpu_timers = &timers_;
        context.trace = &trace_;
        context.plugin_dir = test::plugin_dir();
        context.print = [this](std::string_view t) { output_ += std::string(t) + "\n"; };
        context.session_world = [] { return static_cast<const Bsp*>(nullptr); };
        frames_.emplace(std::move(context));
    }
    void TearDown() override {
        frames_.reset();
        timers_.shutdown();
    }

    FrameSettings settings() const {
        FrameSettings s;
        s.width = kWidth;
        s.height = kHeight;
        s.showroom_time = 1.0f;
        return s;
    }
    // Distinct colours on screen after drawing the showroom over black.
    size_t colours_drawn() {
        glViewport(0, 0, kWidth, kHeight);
        glClearColor(0, 0, 0, 1);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        frames_->draw_showroom(0.0, 0.0f, settings());
        const std::vector<uint8_t> pixels = read_screen(kWidth, kHeight);
        std::set<uint32_t> colours;
        for (size_t i = 0; i < pixels.size(); i += 4) {
            colours.insert(uint32_t(pixels[i]) << 16 | uint32_t(pixels[i + 1]) << 8 |
                           pixels[i + 2]);
        }
        return colours.size();
    }

    GameData game_data_;
    GpuPassTimers timers_;
    FrameTrace trace_;
    std::optional<FrameRenderer> frames_;
};

TEST_F(FrameRendererTest, TheShowroomIsDrawnByTheLoadedPlugin) {
    ASSERT_EQ(frames_->load_plugin("classic"), "");
    EXPECT_EQ(frames_->plugins().active_name(), "classic");
    EXPECT_EQ(colours_drawn(), 1u) << "no showroom yet: nothing is drawn";
    frames_->show_showroom(true);
    EXPECT_TRUE(frames_->showroom_shown());
    EXPECT_GT(colours_drawn(), 20u) << "floor, models and light give many colours";
    frames_->show_showroom(false);
    EXPECT_EQ(colours_drawn(), 1u);
    EXPECT_TRUE(frames_->plugins().models().empty()) << "the showroom's models went with it";
}

TEST_F(FrameRendererTest, AFailedSwapKeepsTheCurrentPlugin) {
    ASSERT_EQ(frames_->load_plugin("classic"), "");
    const std::string why = frames_->load_plugin("no_such_style");
    EXPECT_NE(why, "");
    EXPECT_EQ(frames_->plugins().active_name(), "classic");
    frames_->show_showroom(true);
    EXPECT_GT(colours_drawn(), 20u);
}

InputEvent key(const char* name, bool down = true) {
    InputEvent event;
    event.type = InputEventType::Key;
    event.key = name;
    event.down = down;
    return event;
}

class OverlayTest : public FrameRendererTest {
  protected:
    void SetUp() override {
        FrameRendererTest::SetUp();
        if (HasFatalFailure()) return;
        DemoSessionCallbacks callbacks;
        callbacks.print = [](std::string_view) {};
        callbacks.center_print = [](std::string_view) {};
        callbacks.stuff_text = [](std::string_view) {};
        callbacks.level_unloading = [] {};
        callbacks.level_loaded = [](Level&) {};
        callbacks.level_restarted = [](Level&) {};
        session_.emplace(nullptr, std::move(callbacks));
        // The real data: the menu's and the console's pictures come from gfx.wad.
        auto vfs = Vfs::mount(VfsConfig::for_game(test::data_root(), "lq1"));
        ASSERT_TRUE(vfs) << vfs.error().message;
        vfs_.emplace(std::move(*vfs));
        data_ = load_game_data(&*vfs_);
        overlay_.emplace(host_, data_, &*vfs_, kWidth, kHeight);
        EXPECT_TRUE(overlay_->take_start_messages().empty());
        overlay_->create_menu(frames_->plugins(), *session_, "/nonexistent");
    }
    void TearDown() override {
        overlay_.reset();
        FrameRendererTest::TearDown();
    }
    bool menu_takes(const InputEvent& event) {
        return overlay_->menu_takes_event(event, false, HudScreen{kWidth, kHeight, 1.0f});
    }

    std::optional<Vfs> vfs_;
    GameData data_;
    std::optional<DemoSession> session_;
    std::optional<Overlay> overlay_;
};

TEST_F(OverlayTest, EscapeOpensTheMenuWhichThenTakesTheKeysButNotTheConsoles) {
    EXPECT_FALSE(overlay_->open());
    EXPECT_FALSE(menu_takes(key("UPARROW"))) << "no menu open: keys are the game's";
    EXPECT_TRUE(menu_takes(key("ESCAPE")));
    EXPECT_TRUE(overlay_->menu().active());
    EXPECT_TRUE(overlay_->open());
    EXPECT_TRUE(menu_takes(key("DOWNARROW")));
    EXPECT_FALSE(menu_takes(key("`"))) << "the console's key reaches the console";
    EXPECT_FALSE(menu_takes(key("DOWNARROW", false))) << "releases are never the menu's";
}

TEST_F(OverlayTest, EscapeClosesTheConsoleAndOverNothingOpensTheMenu) {
    overlay_->console().set_open(true);
    EXPECT_TRUE(overlay_->open());
    EXPECT_TRUE(menu_takes(key("ESCAPE")));
    EXPECT_FALSE(overlay_->console().is_open());
    EXPECT_TRUE(overlay_->menu().active()) << "no session runs: the menu shows";
    overlay_->menu().close();
    overlay_->console().set_open(true);
    EXPECT_TRUE(overlay_->menu_takes_event(key("ESCAPE"), true, HudScreen{kWidth, kHeight, 1}));
    EXPECT_FALSE(overlay_->menu().active()) << "over a running session only the console closes";
}

TEST_F(OverlayTest, TheOpenMenuIsDrawnOverTheFrame) {
    glViewport(0, 0, kWidth, kHeight);
    glClearColor(0.5f, 0.5f, 0.5f, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    overlay_->draw(0.0, HudScreen{kWidth, kHeight, 1.0f});
    const std::vector<uint8_t> closed = read_screen(kWidth, kHeight);
    overlay_->menu().open(MenuScreen::Main);
    glClear(GL_COLOR_BUFFER_BIT);
    overlay_->draw(0.0, HudScreen{kWidth, kHeight, 1.0f});
    const std::vector<uint8_t> open = read_screen(kWidth, kHeight);
    size_t changed = 0;
    for (size_t i = 0; i < open.size(); i += 4) changed += open[i] != closed[i];
    EXPECT_GT(changed, size_t(kWidth) * kHeight / 4) << "the menu darkens the screen and draws";
}

}  // namespace
}  // namespace nq

// The SDL window and GL context: creation, reported strings, screenshots read back as PNG,
// the event pump, and errors instead of exits.
#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <cstdlib>

#include "gl/handles.h"
#include "video/png_io.h"
#include "video/screenshot.h"
#include "support/engine_run.h"
#include "support/video_test_support.h"

namespace nq {
namespace {

using test::make_offscreen_window;
using test::TempDir;

constexpr int kWidth = 64, kHeight = 48;

struct Rgb {
    uint8_t r, g, b;
};

void clear_to(Rgb c) {
    glClearColor(c.r / 255.0f, c.g / 255.0f, c.b / 255.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
}

// Every pixel of `rows` [first, last) of the image is `c`.
::testing::AssertionResult rows_are(const RgbImage& image, int first, int last, Rgb c) {
    for (int y = first; y < last; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const uint8_t* p = &image.rgb[(static_cast<size_t>(y) * image.width + x) * 3];
            if (p[0] != c.r || p[1] != c.g || p[2] != c.b) {
                return ::testing::AssertionFailure()
                       << "pixel (" << x << "," << y << ") is " << int(p[0]) << "," << int(p[1])
                       << "," << int(p[2]) << ", expected " << int(c.r) << "," << int(c.g) << ","
                       << int(c.b);
            }
        }
    }
    return ::testing::AssertionSuccess();
}

TEST(VideoWindow, CreatesCoreContextOfAtLeast33AndReportsIt) {
    auto window = make_offscreen_window();
    ASSERT_TRUE(window) << window.error().message;
    const GlInfo& info = window->gl_info();
    EXPECT_GE(info.major * 10 + info.minor, 33);
    EXPECT_FALSE(info.version.empty());
    EXPECT_FALSE(info.renderer.empty());
    EXPECT_FALSE(info.vendor.empty());
    EXPECT_FALSE(info.glsl_version.empty());
    EXPECT_EQ(info.swap_interval, 0);  // vsync off, as timedemo needs

    GLint profile = 0;
    glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
    EXPECT_TRUE(profile & GL_CONTEXT_CORE_PROFILE_BIT);
    GLint major = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    EXPECT_EQ(major, info.major);

    EXPECT_EQ(window->drawable_width(), kWidth);
    EXPECT_EQ(window->drawable_height(), kHeight);
    EXPECT_NE(VideoWindow::gl_proc_address("glDrawArrays"), nullptr);
}

TEST(VideoWindow, ClearedScreenSurvivesScreenshotToPngAndBack) {
    auto window = make_offscreen_window();
    ASSERT_TRUE(window) << window.error().message;
    TempDir dir("nq_video");
    const Rgb colour{51, 102, 204};
    clear_to(colour);

    auto path = next_screenshot_path(dir.path());
    ASSERT_TRUE(path) << path.error().message;
    EXPECT_EQ(std::filesystem::path(*path).filename(), "nprq00.png");
    ASSERT_EQ(save_screenshot(*path, 0, kWidth, kHeight), "");

    auto image = read_png(*path);
    ASSERT_TRUE(image) << image.error().message;
    EXPECT_EQ(image->width, kWidth);
    EXPECT_EQ(image->height, kHeight);
    EXPECT_TRUE(rows_are(*image, 0, kHeight, colour));
}

TEST(VideoWindow, ScreenshotPutsTheTopOfTheScreenFirst) {
    auto window = make_offscreen_window();
    ASSERT_TRUE(window) << window.error().message;
    TempDir dir("nq_video");
    const Rgb blue{0, 0, 255}, red{255, 0, 0};
    clear_to(blue);
    // GL's origin is bottom-left: y in [24, 48) is the top half of the window.
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, kHeight / 2, kWidth, kHeight / 2);
    clear_to(red);
    glDisable(GL_SCISSOR_TEST);

    std::string path = dir.file("flip.png");
    ASSERT_EQ(save_screenshot(path, 0, kWidth, kHeight), "");
    auto image = read_png(path);
    ASSERT_TRUE(image) << image.error().message;
    EXPECT_TRUE(rows_are(*image, 0, kHeight / 2, red));
    EXPECT_TRUE(rows_are(*image, kHeight / 2, kHeight, blue));
}

TEST(VideoWindow, ReadsBackAFramebufferObjectAndRestoresBindings) {
    auto window = make_offscreen_window();
    ASSERT_TRUE(window) << window.error().message;
    npr::gl::Texture texture = npr::gl::Texture::create(nullptr);
    glBindTexture(GL_TEXTURE_2D, texture.id());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 10, 6, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    npr::gl::Framebuffer fbo = npr::gl::Framebuffer::create(nullptr);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture.id(), 0);
    ASSERT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
    const Rgb green{0, 200, 10};
    clear_to(green);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);

    auto image = read_framebuffer_rgb(fbo.id(), 10, 6);
    ASSERT_TRUE(image) << image.error().message;
    EXPECT_EQ(image->rgb.size(), 10u * 6u * 3u);
    EXPECT_TRUE(rows_are(*image, 0, 6, green));

    GLint read_binding = -1, alignment = -1;
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read_binding);
    glGetIntegerv(GL_PACK_ALIGNMENT, &alignment);
    EXPECT_EQ(read_binding, 0);
    EXPECT_EQ(alignment, 4);  // GL's default, put back after reading with alignment 1
}

TEST(VideoWindow, ReadingAnImpossibleSizeIsAnError) {
    auto window = make_offscreen_window();
    ASSERT_TRUE(window) << window.error().message;
    auto image = read_framebuffer_rgb(0, 0, 10);
    ASSERT_FALSE(image);
    EXPECT_NE(image.error().message.find("out of range"), std::string::npos);
}

TEST(VideoWindow, BadWindowSizeIsAnErrorNotAnExit) {
    setenv("SDL_VIDEODRIVER", "offscreen", 1);
    auto window = VideoWindow::create(test::offscreen_options(0, 48));
    ASSERT_FALSE(window);
    EXPECT_NE(window.error().message.find("0x48 is out of range"), std::string::npos)
        << window.error().message;
}

TEST(VideoWindow, MissingVideoDeviceIsAClearError) {
    setenv("SDL_VIDEODRIVER", "no_such_video_driver", 1);
    auto window = VideoWindow::create(test::offscreen_options());
    setenv("SDL_VIDEODRIVER", "offscreen", 1);
    ASSERT_FALSE(window);
    EXPECT_NE(window.error().message.find("no video device"), std::string::npos)
        << window.error().message;
    EXPECT_EQ(SDL_WasInit(SDL_INIT_VIDEO), 0u);  // the failed attempt released SDL video
}

TEST(VideoWindow, DestroyingTheLastWindowReleasesSdlVideo) {
    {
        auto window = make_offscreen_window();
        ASSERT_TRUE(window) << window.error().message;
        VideoWindow moved = std::move(*window);  // ownership moves, nothing is released twice
        EXPECT_NE(moved.sdl_window(), nullptr);
        EXPECT_EQ(window->sdl_window(), nullptr);
        EXPECT_NE(SDL_WasInit(SDL_INIT_VIDEO), 0u);
    }
    EXPECT_EQ(SDL_WasInit(SDL_INIT_VIDEO), 0u);
    EXPECT_EQ(SDL_GL_GetCurrentContext(), nullptr);
}

TEST(VideoWindow, MoveAssignmentReplacesTheWindowAndKeepsTheNewOneWorking) {
    auto first = make_offscreen_window();
    ASSERT_TRUE(first) << first.error().message;
    auto second = make_offscreen_window(32, 16);
    ASSERT_TRUE(second) << second.error().message;
    *first = std::move(*second);  // the 64x48 window and its context go
    EXPECT_EQ(second->sdl_window(), nullptr);
    EXPECT_NE(SDL_WasInit(SDL_INIT_VIDEO), 0u);
    first->make_current();
    EXPECT_EQ(first->drawable_width(), 32);
    const Rgb white{255, 255, 255};
    clear_to(white);
    auto image = read_framebuffer_rgb(0, 32, 16);
    ASSERT_TRUE(image) << image.error().message;
    EXPECT_TRUE(rows_are(*image, 0, 16, white));
}

TEST(VideoWindow, EventPumpTranslatesQueuedSdlEvents) {
    auto window = make_offscreen_window();
    ASSERT_TRUE(window) << window.error().message;
    InputEvent ignored;
    while (window->poll_event(ignored)) {
    }  // drain whatever window creation queued

    SDL_Event key{};
    key.type = SDL_KEYDOWN;
    key.key.state = SDL_PRESSED;
    key.key.keysym.scancode = SDL_SCANCODE_GRAVE;
    SDL_Event wheel{};
    wheel.type = SDL_MOUSEWHEEL;
    wheel.wheel.y = -1;
    wheel.wheel.direction = SDL_MOUSEWHEEL_NORMAL;
    SDL_Event quit{};
    quit.type = SDL_QUIT;
    ASSERT_EQ(SDL_PushEvent(&key), 1);
    ASSERT_EQ(SDL_PushEvent(&wheel), 1);
    ASSERT_EQ(SDL_PushEvent(&quit), 1);

    InputEvent e;
    ASSERT_TRUE(window->poll_event(e));
    EXPECT_EQ(e.type, InputEventType::Key);
    EXPECT_STREQ(e.key, "`");
    EXPECT_TRUE(e.down);
    ASSERT_TRUE(window->poll_event(e));
    EXPECT_STREQ(e.key, "MWHEELDOWN");
    EXPECT_TRUE(e.down);
    ASSERT_TRUE(window->poll_event(e));
    EXPECT_STREQ(e.key, "MWHEELDOWN");
    EXPECT_FALSE(e.down);
    ASSERT_TRUE(window->poll_event(e));
    EXPECT_EQ(e.type, InputEventType::Quit);
    EXPECT_FALSE(window->poll_event(e));
}

TEST(VideoWindow, ResizeChangesTheDrawableSize) {
    auto window = make_offscreen_window();
    ASSERT_TRUE(window) << window.error().message;
    window->set_window_size(80, 60);
    EXPECT_EQ(window->drawable_width(), 80);
    EXPECT_EQ(window->drawable_height(), 60);
}

}  // namespace
}  // namespace nq

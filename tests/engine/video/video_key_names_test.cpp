// SDL physical keys and mouse buttons -> Quake key names, and SDL events -> engine events.
#include <gtest/gtest.h>

#include <array>
#include <cstring>

#include "host/key_names.h"
#include "video/sdl_event_translation.h"
#include "video/sdl_key_names.h"

namespace nq {
namespace {

TEST(VideoKeyNames, LettersDigitsAndPunctuationAreTheCharacter) {
    EXPECT_STREQ(key_name_for_scancode(SDL_SCANCODE_A), "a");
    EXPECT_STREQ(key_name_for_scancode(SDL_SCANCODE_Z), "z");
    EXPECT_STREQ(key_name_for_scancode(SDL_SCANCODE_1), "1");
    EXPECT_STREQ(key_name_for_scancode(SDL_SCANCODE_0), "0");      // after 9 in SDL's numbering
    EXPECT_STREQ(key_name_for_scancode(SDL_SCANCODE_GRAVE), "`");  // the console key
    EXPECT_STREQ(key_name_for_scancode(SDL_SCANCODE_LEFTBRACKET), "[");
    EXPECT_STREQ(key_name_for_scancode(SDL_SCANCODE_SEMICOLON), "SEMICOLON");
}

TEST(VideoKeyNames, SpecialKeysHaveQuakeNames) {
    EXPECT_STREQ(key_name_for_scancode(SDL_SCANCODE_ESCAPE), "ESCAPE");
    EXPECT_STREQ(key_name_for_scancode(SDL_SCANCODE_RETURN), "ENTER");
    EXPECT_STREQ(key_name_for_scancode(SDL_SCANCODE_TAB), "TAB");
    EXPECT_STREQ(key_name_for_scancode(SDL_SCANCODE_SPACE), "SPACE");
    EXPECT_STREQ(key_name_for_scancode(SDL_SCANCODE_BACKSPACE), "BACKSPACE");
    EXPECT_STREQ(key_name_for_scancode(SDL_SCANCODE_UP), "UPARROW");
    EXPECT_STREQ(key_name_for_scancode(SDL_SCANCODE_DOWN), "DOWNARROW");
    EXPECT_STREQ(key_name_for_scancode(SDL_SCANCODE_LEFT), "LEFTARROW");
    EXPECT_STREQ(key_name_for_scancode(SDL_SCANCODE_RIGHT), "RIGHTARROW");
    EXPECT_STREQ(key_name_for_scancode(SDL_SCANCODE_F1), "F1");
    EXPECT_STREQ(key_name_for_scancode(SDL_SCANCODE_F12), "F12");
    EXPECT_STREQ(key_name_for_scancode(SDL_SCANCODE_PAGEUP), "PGUP");
    EXPECT_STREQ(key_name_for_scancode(SDL_SCANCODE_PAGEDOWN), "PGDN");
    EXPECT_STREQ(key_name_for_scancode(SDL_SCANCODE_HOME), "HOME");
    EXPECT_STREQ(key_name_for_scancode(SDL_SCANCODE_END), "END");
    EXPECT_STREQ(key_name_for_scancode(SDL_SCANCODE_INSERT), "INS");
    EXPECT_STREQ(key_name_for_scancode(SDL_SCANCODE_DELETE), "DEL");
    EXPECT_STREQ(key_name_for_scancode(SDL_SCANCODE_PAUSE), "PAUSE");
    EXPECT_STREQ(key_name_for_scancode(SDL_SCANCODE_KP_ENTER), "KP_ENTER");
}

TEST(VideoKeyNames, LeftAndRightModifiersShareOneName) {
    EXPECT_STREQ(key_name_for_scancode(SDL_SCANCODE_LSHIFT), "SHIFT");
    EXPECT_STREQ(key_name_for_scancode(SDL_SCANCODE_RSHIFT), "SHIFT");
    EXPECT_STREQ(key_name_for_scancode(SDL_SCANCODE_LCTRL), "CTRL");
    EXPECT_STREQ(key_name_for_scancode(SDL_SCANCODE_RCTRL), "CTRL");
    EXPECT_STREQ(key_name_for_scancode(SDL_SCANCODE_LALT), "ALT");
    EXPECT_STREQ(key_name_for_scancode(SDL_SCANCODE_RALT), "ALT");
}

TEST(VideoKeyNames, KeysWithoutAQuakeNameGiveNull) {
    EXPECT_EQ(key_name_for_scancode(SDL_SCANCODE_UNKNOWN), nullptr);
    EXPECT_EQ(key_name_for_scancode(SDL_SCANCODE_APPLICATION), nullptr);
    EXPECT_EQ(key_name_for_scancode(SDL_SCANCODE_F13), nullptr);
}

// Every name the window can produce must be one `bind` accepts, spelled canonically.
TEST(VideoKeyNames, EveryProducedNameIsACanonicalBindName) {
    int named = 0;
    for (int sc = 0; sc < SDL_NUM_SCANCODES; ++sc) {
        const char* name = key_name_for_scancode(static_cast<SDL_Scancode>(sc));
        if (!name) continue;
        ++named;
        auto canonical = canonical_key_name(name);
        ASSERT_TRUE(canonical.has_value()) << "scancode " << sc << " -> " << name;
        EXPECT_EQ(*canonical, name) << "scancode " << sc;
    }
    EXPECT_GE(named, 26 + 10 + 12 + 20);
    for (uint8_t button = SDL_BUTTON_LEFT; button <= SDL_BUTTON_X2; ++button) {
        auto canonical = canonical_key_name(key_name_for_mouse_button(button));
        ASSERT_TRUE(canonical.has_value());
        EXPECT_EQ(*canonical, key_name_for_mouse_button(button));
    }
    EXPECT_TRUE(canonical_key_name(kKeyMouseWheelUp).has_value());
    EXPECT_TRUE(canonical_key_name(kKeyMouseWheelDown).has_value());
}

TEST(VideoKeyNames, MouseButtonsFollowQuakesNumbering) {
    EXPECT_STREQ(key_name_for_mouse_button(SDL_BUTTON_LEFT), "MOUSE1");
    EXPECT_STREQ(key_name_for_mouse_button(SDL_BUTTON_RIGHT), "MOUSE2");
    EXPECT_STREQ(key_name_for_mouse_button(SDL_BUTTON_MIDDLE), "MOUSE3");
    EXPECT_STREQ(key_name_for_mouse_button(SDL_BUTTON_X1), "MOUSE4");
    EXPECT_STREQ(key_name_for_mouse_button(SDL_BUTTON_X2), "MOUSE5");
    EXPECT_EQ(key_name_for_mouse_button(9), nullptr);
}

struct Translated {
    int count = 0;
    std::array<InputEvent, kMaxEventsPerSdlEvent> events{};
};

Translated translate(const SDL_Event& e) {
    Translated t;
    t.count = translate_sdl_event(e, t.events);
    return t;
}

TEST(VideoEventTranslation, KeyDownRepeatAndUp) {
    SDL_Event e{};
    e.type = SDL_KEYDOWN;
    e.key.state = SDL_PRESSED;
    e.key.repeat = 1;
    e.key.keysym.scancode = SDL_SCANCODE_BACKSPACE;
    Translated t = translate(e);
    ASSERT_EQ(t.count, 1);
    EXPECT_EQ(t.events[0].type, InputEventType::Key);
    EXPECT_STREQ(t.events[0].key, "BACKSPACE");
    EXPECT_TRUE(t.events[0].down);
    EXPECT_TRUE(t.events[0].repeat);

    e.type = SDL_KEYUP;
    e.key.state = SDL_RELEASED;
    e.key.repeat = 0;
    t = translate(e);
    ASSERT_EQ(t.count, 1);
    EXPECT_FALSE(t.events[0].down);
    EXPECT_FALSE(t.events[0].repeat);

    e.key.keysym.scancode = SDL_SCANCODE_APPLICATION;  // no Quake name: dropped
    EXPECT_EQ(translate(e).count, 0);
}

TEST(VideoEventTranslation, WheelNotchIsAPressAndRelease) {
    SDL_Event e{};
    e.type = SDL_MOUSEWHEEL;
    e.wheel.y = 2;
    e.wheel.direction = SDL_MOUSEWHEEL_NORMAL;
    Translated t = translate(e);
    ASSERT_EQ(t.count, 2);
    EXPECT_STREQ(t.events[0].key, "MWHEELUP");
    EXPECT_TRUE(t.events[0].down);
    EXPECT_STREQ(t.events[1].key, "MWHEELUP");
    EXPECT_FALSE(t.events[1].down);

    e.wheel.direction = SDL_MOUSEWHEEL_FLIPPED;  // "natural" scrolling reports inverted y
    EXPECT_STREQ(translate(e).events[0].key, "MWHEELDOWN");
    e.wheel.y = 0;
    e.wheel.x = 1;  // horizontal scrolling has no key
    EXPECT_EQ(translate(e).count, 0);
}

TEST(VideoEventTranslation, TextMotionButtonResizeAndQuit) {
    SDL_Event text{};
    text.type = SDL_TEXTINPUT;
    std::strcpy(text.text.text, "\xc3\xa9x");  // "éx" in UTF-8
    Translated t = translate(text);
    ASSERT_EQ(t.count, 1);
    EXPECT_EQ(t.events[0].type, InputEventType::Text);
    EXPECT_STREQ(t.events[0].text.data(), "\xc3\xa9x");

    SDL_Event motion{};
    motion.type = SDL_MOUSEMOTION;
    motion.motion.xrel = -3;
    motion.motion.yrel = 7;
    t = translate(motion);
    ASSERT_EQ(t.count, 1);
    EXPECT_EQ(t.events[0].type, InputEventType::MouseMotion);
    EXPECT_EQ(t.events[0].dx, -3);
    EXPECT_EQ(t.events[0].dy, 7);

    SDL_Event button{};
    button.type = SDL_MOUSEBUTTONDOWN;
    button.button.button = SDL_BUTTON_RIGHT;
    button.button.state = SDL_PRESSED;
    t = translate(button);
    ASSERT_EQ(t.count, 1);
    EXPECT_STREQ(t.events[0].key, "MOUSE2");
    EXPECT_TRUE(t.events[0].down);

    SDL_Event resize{};
    resize.type = SDL_WINDOWEVENT;
    resize.window.event = SDL_WINDOWEVENT_SIZE_CHANGED;
    resize.window.data1 = 800;
    resize.window.data2 = 600;
    t = translate(resize);
    ASSERT_EQ(t.count, 1);
    EXPECT_EQ(t.events[0].type, InputEventType::Resize);
    EXPECT_EQ(t.events[0].width, 800);
    EXPECT_EQ(t.events[0].height, 600);

    SDL_Event quit{};
    quit.type = SDL_QUIT;
    EXPECT_EQ(translate(quit).events[0].type, InputEventType::Quit);

    SDL_Event other{};
    other.type = SDL_JOYAXISMOTION;
    EXPECT_EQ(translate(other).count, 0);
}

}  // namespace
}  // namespace nq

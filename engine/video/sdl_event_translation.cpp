#include "video/sdl_event_translation.h"

#include <algorithm>
#include <cstring>

#include "video/sdl_key_names.h"

namespace nq {
namespace {

InputEvent key_event(const char* name, bool down, bool repeat = false) {
    InputEvent e;
    e.type = InputEventType::Key;
    e.key = name;
    e.down = down;
    e.repeat = repeat;
    return e;
}

int translate_keyboard(const SDL_KeyboardEvent& key, InputEvent& out) {
    const char* name = key_name_for_scancode(key.keysym.scancode);
    if (!name) return 0;
    out = key_event(name, key.state == SDL_PRESSED, key.repeat != 0);
    return 1;
}

int translate_text(const SDL_TextInputEvent& text, InputEvent& out) {
    out = InputEvent{};
    out.type = InputEventType::Text;
    size_t length = strnlen(text.text, sizeof text.text);
    length = std::min(length, out.text.size() - 1);
    std::memcpy(out.text.data(), text.text, length);
    out.text[length] = '\0';
    return length > 0 ? 1 : 0;
}

int translate_mouse_button(const SDL_MouseButtonEvent& button, InputEvent& out) {
    const char* name = key_name_for_mouse_button(button.button);
    if (!name) return 0;
    out = key_event(name, button.state == SDL_PRESSED);
    return 1;
}

int translate_wheel(const SDL_MouseWheelEvent& wheel, std::span<InputEvent, 2> out) {
    int notches = wheel.direction == SDL_MOUSEWHEEL_FLIPPED ? -wheel.y : wheel.y;
    if (notches == 0) return 0;  // horizontal scrolling has no Quake key
    const char* name = notches > 0 ? kKeyMouseWheelUp : kKeyMouseWheelDown;
    out[0] = key_event(name, true);
    out[1] = key_event(name, false);
    return 2;
}

int translate_window(const SDL_WindowEvent& window, InputEvent& out) {
    out = InputEvent{};
    switch (window.event) {
        case SDL_WINDOWEVENT_SIZE_CHANGED:
            out.type = InputEventType::Resize;
            out.width = window.data1;
            out.height = window.data2;
            return 1;
        case SDL_WINDOWEVENT_FOCUS_GAINED:
            out.type = InputEventType::FocusGained;
            return 1;
        case SDL_WINDOWEVENT_FOCUS_LOST:
            out.type = InputEventType::FocusLost;
            return 1;
        default:
            return 0;
    }
}

}  // namespace

int translate_sdl_event(const SDL_Event& event, std::span<InputEvent, kMaxEventsPerSdlEvent> out) {
    switch (event.type) {
        case SDL_KEYDOWN:
        case SDL_KEYUP:
            return translate_keyboard(event.key, out[0]);
        case SDL_TEXTINPUT:
            return translate_text(event.text, out[0]);
        case SDL_MOUSEBUTTONDOWN:
        case SDL_MOUSEBUTTONUP:
            return translate_mouse_button(event.button, out[0]);
        case SDL_MOUSEWHEEL:
            return translate_wheel(event.wheel, out);
        case SDL_MOUSEMOTION:
            out[0] = InputEvent{};
            out[0].type = InputEventType::MouseMotion;
            out[0].dx = event.motion.xrel;
            out[0].dy = event.motion.yrel;
            out[0].x = event.motion.x;
            out[0].y = event.motion.y;
            return 1;
        case SDL_WINDOWEVENT:
            return translate_window(event.window, out[0]);
        case SDL_QUIT:
            out[0] = InputEvent{};
            out[0].type = InputEventType::Quit;
            return 1;
        default:
            return 0;
    }
}

}  // namespace nq

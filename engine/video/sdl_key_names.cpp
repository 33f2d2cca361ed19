#include "video/sdl_key_names.h"

namespace nq {
namespace {

struct NamedScancode {
    SDL_Scancode scancode;
    const char* name;
};

// SDL numbers A..Z, 1..9 0 and F1..F12 contiguously; these cover the rest.
constexpr NamedScancode kNamedScancodes[] = {
    {SDL_SCANCODE_RETURN, "ENTER"},
    {SDL_SCANCODE_ESCAPE, "ESCAPE"},
    {SDL_SCANCODE_BACKSPACE, "BACKSPACE"},
    {SDL_SCANCODE_TAB, "TAB"},
    {SDL_SCANCODE_SPACE, "SPACE"},
    {SDL_SCANCODE_MINUS, "-"},
    {SDL_SCANCODE_EQUALS, "="},
    {SDL_SCANCODE_LEFTBRACKET, "["},
    {SDL_SCANCODE_RIGHTBRACKET, "]"},
    {SDL_SCANCODE_BACKSLASH, "\\"},
    {SDL_SCANCODE_SEMICOLON, "SEMICOLON"},  // ';' would split a bind command in two
    {SDL_SCANCODE_APOSTROPHE, "'"},
    {SDL_SCANCODE_GRAVE, "`"},  // the console key
    {SDL_SCANCODE_COMMA, ","},
    {SDL_SCANCODE_PERIOD, "."},
    {SDL_SCANCODE_SLASH, "/"},
    {SDL_SCANCODE_CAPSLOCK, "CAPSLOCK"},
    {SDL_SCANCODE_PAUSE, "PAUSE"},
    {SDL_SCANCODE_INSERT, "INS"},
    {SDL_SCANCODE_HOME, "HOME"},
    {SDL_SCANCODE_PAGEUP, "PGUP"},
    {SDL_SCANCODE_DELETE, "DEL"},
    {SDL_SCANCODE_END, "END"},
    {SDL_SCANCODE_PAGEDOWN, "PGDN"},
    {SDL_SCANCODE_RIGHT, "RIGHTARROW"},
    {SDL_SCANCODE_LEFT, "LEFTARROW"},
    {SDL_SCANCODE_DOWN, "DOWNARROW"},
    {SDL_SCANCODE_UP, "UPARROW"},
    {SDL_SCANCODE_LCTRL, "CTRL"},
    {SDL_SCANCODE_RCTRL, "CTRL"},
    {SDL_SCANCODE_LSHIFT, "SHIFT"},
    {SDL_SCANCODE_RSHIFT, "SHIFT"},
    {SDL_SCANCODE_LALT, "ALT"},
    {SDL_SCANCODE_RALT, "ALT"},
    {SDL_SCANCODE_KP_DIVIDE, "KP_SLASH"},
    {SDL_SCANCODE_KP_MULTIPLY, "KP_STAR"},
    {SDL_SCANCODE_KP_MINUS, "KP_MINUS"},
    {SDL_SCANCODE_KP_PLUS, "KP_PLUS"},
    {SDL_SCANCODE_KP_ENTER, "KP_ENTER"},
    {SDL_SCANCODE_KP_1, "KP_END"},
    {SDL_SCANCODE_KP_2, "KP_DOWNARROW"},
    {SDL_SCANCODE_KP_3, "KP_PGDN"},
    {SDL_SCANCODE_KP_4, "KP_LEFTARROW"},
    {SDL_SCANCODE_KP_5, "KP_5"},
    {SDL_SCANCODE_KP_6, "KP_RIGHTARROW"},
    {SDL_SCANCODE_KP_7, "KP_HOME"},
    {SDL_SCANCODE_KP_8, "KP_UPARROW"},
    {SDL_SCANCODE_KP_9, "KP_PGUP"},
    {SDL_SCANCODE_KP_0, "KP_INS"},
    {SDL_SCANCODE_KP_PERIOD, "KP_DEL"},
};

constexpr const char* kLetters[] = {"a", "b", "c", "d", "e", "f", "g", "h", "i",
                                    "j", "k", "l", "m", "n", "o", "p", "q", "r",
                                    "s", "t", "u", "v", "w", "x", "y", "z"};
constexpr const char* kDigits[] = {"1", "2", "3", "4", "5", "6", "7", "8", "9", "0"};
constexpr const char* kFunctionKeys[] = {"F1", "F2", "F3", "F4",  "F5",  "F6",
                                         "F7", "F8", "F9", "F10", "F11", "F12"};

// Name from a table indexed by scancode - first, or nullptr outside the table.
template <size_t N>
const char* from_run(const char* const (&names)[N], SDL_Scancode first, SDL_Scancode scancode) {
    int index = static_cast<int>(scancode) - static_cast<int>(first);
    if (index < 0 || index >= static_cast<int>(N)) return nullptr;
    return names[index];
}

}  // namespace

const char* key_name_for_scancode(SDL_Scancode scancode) {
    if (const char* name = from_run(kLetters, SDL_SCANCODE_A, scancode)) return name;
    if (const char* name = from_run(kDigits, SDL_SCANCODE_1, scancode)) return name;
    if (const char* name = from_run(kFunctionKeys, SDL_SCANCODE_F1, scancode)) return name;
    for (const NamedScancode& entry : kNamedScancodes) {
        if (entry.scancode == scancode) return entry.name;
    }
    return nullptr;
}

const char* key_name_for_mouse_button(uint8_t sdl_button) {
    switch (sdl_button) {
        case SDL_BUTTON_LEFT:
            return "MOUSE1";
        case SDL_BUTTON_RIGHT:
            return "MOUSE2";
        case SDL_BUTTON_MIDDLE:
            return "MOUSE3";
        case SDL_BUTTON_X1:
            return "MOUSE4";
        case SDL_BUTTON_X2:
            return "MOUSE5";
        default:
            return nullptr;
    }
}

}  // namespace nq

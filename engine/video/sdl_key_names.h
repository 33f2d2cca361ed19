// Quake key names for SDL's physical keys (scancodes) and mouse buttons.
//
// Keys are mapped by physical position (scancode) with US-layout names, so WASD and the console
// key stay where they are on any keyboard layout; typed characters come separately as text
// input. The names are the canonical ones of host/key_names.h: letters lower case ("a"), digits
// and punctuation as the character ("1", "[", "`"), everything else upper case ("ESCAPE", "F1",
// "UPARROW", "SEMICOLON", "MOUSE1", "KP_ENTER").
#pragma once

#include <SDL.h>

#include <cstdint>

namespace nq {

inline constexpr const char* kKeyMouseWheelUp = "MWHEELUP";
inline constexpr const char* kKeyMouseWheelDown = "MWHEELDOWN";

// The key's name (static storage), or nullptr for keys Quake has no name for.
const char* key_name_for_scancode(SDL_Scancode scancode);

// SDL buttons 1..5 (left, middle, right, X1, X2) as Quake's MOUSE1 (left), MOUSE3 (middle),
// MOUSE2 (right), MOUSE4, MOUSE5; nullptr for other buttons.
const char* key_name_for_mouse_button(uint8_t sdl_button);

}  // namespace nq

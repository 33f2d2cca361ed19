// Engine-side input events: what the window's event pump hands to the host, with no SDL types.
#pragma once

#include <array>
#include <cstdint>

namespace nq {

enum class InputEventType : uint8_t {
    Key,          // a key or mouse button (or wheel notch) went down or up
    Text,         // typed text for the console (UTF-8, layout-aware)
    MouseMotion,  // relative mouse movement in pixels
    Resize,       // the drawable changed size
    FocusGained,
    FocusLost,
    Quit,  // the window was closed or the OS asked to quit
};

// Plain data, no heap: the pump fills these every frame.
struct InputEvent {
    InputEventType type = InputEventType::Quit;
    const char* key = nullptr;      // Key: canonical Quake key name (static storage)
    bool down = false;              // Key: pressed (true) or released
    bool repeat = false;            // Key: auto-repeat of a held key
    std::array<char, 32> text{};    // Text: NUL-terminated UTF-8
    int32_t dx = 0, dy = 0;         // MouseMotion: the movement
    int32_t x = 0, y = 0;           // MouseMotion: the pointer's place in the window
    int32_t width = 0, height = 0;  // Resize: new drawable size in pixels
};

}  // namespace nq

// Translation of one SDL event into zero, one or two engine input events.
#pragma once

#include <SDL.h>

#include <span>

#include "video/input_event.h"

namespace nq {

// Most SDL events give one engine event, ignored ones none, and a wheel notch two (the wheel
// "key" goes down and straight back up, as Quake expects).
inline constexpr int kMaxEventsPerSdlEvent = 2;

// Writes the translated events to `out` and returns how many. Resize events carry the window
// size from SDL; the window replaces it with the drawable size (they differ on HiDPI screens).
int translate_sdl_event(const SDL_Event& event, std::span<InputEvent, kMaxEventsPerSdlEvent> out);

}  // namespace nq

// Creating an OpenGL core-profile context for an SDL window and describing it.
#pragma once

#include <SDL.h>

#include <string>

#include "video/gl_info.h"

namespace nq {

// Window-creation attributes every context needs (RGB8, depth 24, stencil 8, double-buffered).
void request_framebuffer_attributes();

// Tries 4.5 core, then 3.3 core. On success *out is the new (current) context and the result is
// empty; otherwise the result says what failed.
std::string create_core_context(SDL_Window* window, SDL_GLContext* out);

// True when the calling thread has a current GL context.
bool gl_context_is_current();

// Version, renderer and vendor strings of the current context.
GlInfo describe_current_context();

}  // namespace nq

// The console's GLSL program: screen-pixel quads (y down), each either a solid colour or a
// texel of the bound texture (the font atlas or the background) times the vertex colour.
#pragma once

#include "common/result.h"
#include "video/gl_objects.h"

namespace nq {

// Vertex attribute locations, matching QuadVertex (quad_batch.h).
inline constexpr GLuint kConsolePositionAttribute = 0;
inline constexpr GLuint kConsoleUvAttribute = 1;
inline constexpr GLuint kConsoleColourAttribute = 2;
inline constexpr GLuint kConsoleTexturedAttribute = 3;

// Uniforms: vec2 "screen_size" (pixels), sampler2D "image" (texture unit 0, set here).
Result<GlProgram> build_console_program();

}  // namespace nq

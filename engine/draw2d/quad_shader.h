// The 2D overlays' GLSL program: screen-pixel quads (y down), each either a solid colour or a
// texel of the bound texture (a font, a picture atlas, a background) times the vertex colour.
#pragma once

#include "common/result.h"
#include "gl/program.h"

namespace nq {

// Vertex attribute locations, matching QuadVertex (quad_batch.h).
inline constexpr GLuint kQuadPositionAttribute = 0;
inline constexpr GLuint kQuadUvAttribute = 1;
inline constexpr GLuint kQuadColourAttribute = 2;
inline constexpr GLuint kQuadSamplingAttribute = 3;

// Uniforms: vec2 "screen_size" (pixels), sampler2D "image" (texture unit 0, set here).
Result<npr::gl::Program> build_quad_program();

}  // namespace nq

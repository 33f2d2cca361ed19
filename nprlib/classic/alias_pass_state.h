// GL state every alias-model face drawer shares (classic look, technical, illustrative): Quake's
// clockwise winding culled, translucent entities blended without depth writes, and the state
// restored when the pass ends.
#pragma once

#include <epoxy/gl.h>

namespace nq::npr::classic {

// Culls the inside of models: Quake winds alias triangles clockwise seen from outside.
void begin_alias_face_culling();

// The bound vertex array's `index_count` indices as triangles; blended (alpha from the shader)
// without depth writes when `translucent`.
void draw_alias_elements(GLsizei index_count, bool translucent);

// Undoes begin_alias_face_culling and the blend state; unbinds vertex array and program.
void end_alias_face_pass();

}  // namespace nq::npr::classic

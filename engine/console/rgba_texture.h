// Uploading an RGBA image (the console font, the console background) into a GL texture.
#pragma once

#include <epoxy/gl.h>

#include <cstdint>

namespace nq {

// Sets `texture`'s image to `rgba` (width*height*4 bytes, top row first) with nearest
// filtering and clamped edges. Restores the 2D texture binding and the unpack state it uses.
void upload_rgba_texture(GLuint texture, int width, int height, const uint8_t* rgba);

}  // namespace nq

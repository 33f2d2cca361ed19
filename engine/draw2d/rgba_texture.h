// Uploading an RGBA image (a font, a picture atlas, a background) into a GL texture.
#pragma once

#include <epoxy/gl.h>

#include <cstdint>

namespace nq {

enum class TextureFilter {
    Nearest,  // whole-multiple scales keep texels on pixels: exact
    Linear,   // smooth at fractional scales (the status bar at 1.6, as QuakeSpasm draws it)
};

// Sets `texture`'s image to `rgba` (width*height*4 bytes, top row first) with `filter` and
// clamped edges. Restores the 2D texture binding and the unpack state it uses.
void upload_rgba_texture(GLuint texture, int width, int height, const uint8_t* rgba,
                         TextureFilter filter = TextureFilter::Nearest);

}  // namespace nq

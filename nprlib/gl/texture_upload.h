// Texture creation and upload helpers (RGBA8, optional mipmaps), plus the one sampling setup
// the classic look uses.
#pragma once

#include <epoxy/gl.h>

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "gl/handles.h"
#include "gl/palette_image.h"

namespace nq::npr::gl {

struct Sampling {
    GLenum min_filter;
    GLenum mag_filter;
    GLenum wrap;
    bool mipmaps;
};

// QuakeSpasm's default gl_texturemode is GL_LINEAR_MIPMAP_LINEAR (trilinear); GLQuake's was
// GL_LINEAR_MIPMAP_NEAREST. The classic look follows QuakeSpasm. A constant until a cvar exists.
inline constexpr Sampling kMipmappedRepeat = {GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_REPEAT, true};
inline constexpr Sampling kMipmappedClamp = {GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE,
                                             true};
inline constexpr Sampling kLinearClamp = {GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE, false};
inline constexpr Sampling kNearestClamp = {GL_NEAREST, GL_NEAREST, GL_CLAMP_TO_EDGE, false};
inline constexpr Sampling kNearestRepeat = {GL_NEAREST, GL_NEAREST, GL_REPEAT, false};

// A 2D RGBA8 texture from width x height RGBA bytes (rows bottom-to-top as GL sees them: row 0
// of `rgba` is t = 0). Mipmaps are generated when sampling asks for them.
Texture create_rgba8_texture(ObjectTracker* tracker, int width, int height,
                             std::span<const uint8_t> rgba, const Sampling& sampling);

// A 1x1 texture of one colour (black for "no fullbrights", white for "no lightmap").
Texture create_solid_texture(ObjectTracker* tracker, uint8_t r, uint8_t g, uint8_t b, uint8_t a);

// Rewrites a texture's RGBA8 texels before they are uploaded (a style's abstraction of the
// world's textures, for instance). Runs at load time only.
using RgbaFilter = std::function<void(int width, int height, std::vector<uint8_t>& rgba)>;

// Palette image -> RGBA8 texels as create_palette_texture uploads them: expanded, transparent
// texels bled, then `filter` (may be null). Touches no GL state, so it may run on any thread.
void expand_palette_texels(int width, int height, std::span<const uint8_t> pixels,
                           const uint8_t* palette_rgb, PaletteExpansion expansion,
                           std::vector<uint8_t>& rgba, const RgbaFilter* filter = nullptr);

// Palette image -> RGBA8 texture in one call; `scratch` is reused between calls. `filter`, when
// given, sees the expanded texels first.
Texture create_palette_texture(ObjectTracker* tracker, int width, int height,
                               std::span<const uint8_t> pixels, const uint8_t* palette_rgb,
                               PaletteExpansion expansion, const Sampling& sampling,
                               std::vector<uint8_t>& scratch, const RgbaFilter* filter = nullptr);

// The fullbright mask of a palette image as a texture, or an empty handle when it has no
// fullbright pixel (callers then bind a shared black texture).
Texture create_fullbright_texture(ObjectTracker* tracker, int width, int height,
                                  std::span<const uint8_t> pixels, const uint8_t* palette_rgb,
                                  const Sampling& sampling, std::vector<uint8_t>& scratch);

void apply_sampling(GLenum target, const Sampling& sampling);

}  // namespace nq::npr::gl

// GPU textures of a brush model's nqr_textures, by kind:
//   lit     — base colour with fullbright pixels painted black + a fullbright mask added unlit
//   fence   — "{name" textures: as lit, index 255 transparent (alpha-tested)
//   sky     — the 256x128 sky split in two 128x128 layers: right half the solid back layer,
//             left half the front layer, transparent where the index is 0
//   liquid  — "*name": full colours, drawn unlit and warped
#pragma once

#include <cstdint>
#include <vector>

#include "gl/handles.h"
#include "gl/texture_upload.h"
#include "nqr_renderer.h"

namespace nq::npr::classic {

enum class SurfaceKind : uint8_t { lit, fence, sky, liquid };

struct BrushTextureGpu {
    gl::Texture base;        // sky: the back layer
    gl::Texture fullbright;  // empty when the texture has no fullbright pixel
    gl::Texture sky_front;   // sky only
    SurfaceKind kind = SurfaceKind::lit;
    float size[2] = {1, 1};  // texels, for turning texel coordinates into 0..1
};

SurfaceKind surface_kind_of(const nqr_texture& texture);

// One entry per brush.textures element, plus a last one: the placeholder for surfaces whose
// texture index is -1 or out of range. `filter` (may be null) rewrites the base colours of
// every kind but sky before upload; fullbright masks stay as the palette says.
std::vector<BrushTextureGpu> create_brush_textures(gl::ObjectTracker* tracker,
                                                   const nqr_brush_model& brush,
                                                   const uint8_t* palette_rgb,
                                                   const gl::RgbaFilter* filter = nullptr);

}  // namespace nq::npr::classic

// Many small pictures packed into one RGBA image, so that a whole overlay (the status bar with
// its numbers, faces and icons) is one texture and one draw call.
//
//   std::vector<RgbaImage> pictures = ...;
//   PictureAtlas atlas = pack_pictures(pictures);
//   upload atlas.image; draw picture i with QuadBatch::image(..., atlas.pictures[i].region)
//
// The atlas may be sampled with linear filtering: each picture's edge pixels are repeated
// into a one-pixel border around it (so its edges blend with themselves, not a neighbour or
// the empty space between), and its transparent pixels take the colour of their opaque
// neighbours (so a filtered edge fades out instead of darkening).
#pragma once

#include <span>
#include <vector>

#include "draw2d/quad_batch.h"
#include "draw2d/rgba_image.h"

namespace nq {

struct AtlasPicture {
    int width = 0;  // pixels; 0 for an empty picture, which has no place in the atlas
    int height = 0;
    TextureRegion region;

    bool present() const { return width > 0 && height > 0; }
};

struct PictureAtlas {
    RgbaImage image;                     // empty when no picture had pixels
    std::vector<AtlasPicture> pictures;  // one per input picture, in the same order
};

inline constexpr int kAtlasWidth = 512;

// Packs the pictures row by row (tallest first) into an image kAtlasWidth wide (wider when a
// picture is), as tall as needed.
PictureAtlas pack_pictures(std::span<const RgbaImage> pictures);

}  // namespace nq

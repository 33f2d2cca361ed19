// The console font as an RGBA image ready for the GPU: Quake's conchars (from gfx.wad) coloured
// with the game palette, or the built-in fallback font when there is no game data.
//
// Layout either way: 128x128 pixels, 16x16 glyphs of 8x8, glyph n at column n % 16, row n / 16.
// Glyphs 128..255 are the alternate (gold/red) forms of 0..127, used by bytes with bit 7 set.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "common/result.h"
#include "draw2d/quad_batch.h"
#include "draw2d/rgba_image.h"
#include "formats/lmp.h"
#include "formats/palette.h"
#include "formats/wad.h"

namespace nq {

inline constexpr int kFontImageSize = kConcharsSize;              // 128
inline constexpr int kFontGlyphsPerRow = kFontSheetGlyphsPerRow;  // 16
inline constexpr uint8_t kConcharsTransparentIndex = 0;

// Conchars indices (128*128 of them; fewer or more is an error) through the palette; index 0
// is transparent.
Result<RgbaImage> conchars_to_rgba(std::span<const uint8_t> pixels, const Palette& palette);

// Finds "conchars" in gfx.wad, decodes it and colours it.
Result<RgbaImage> load_conchars_font(const Wad& gfx_wad, const Palette& palette);

// The built-in font: printable ASCII in light grey, the same glyphs gold in the upper half.
const RgbaImage& fallback_font();

}  // namespace nq

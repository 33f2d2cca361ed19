// The built-in console font's glyph drawings (printable ASCII), as text: what the console draws
// with when the game has no gfx.wad conchars (the showroom runs without game data).
#pragma once

#include <span>

namespace nq {

inline constexpr int kSheetGlyphWidth = 5;
inline constexpr int kSheetGlyphHeight = 8;
inline constexpr int kSheetGlyphsPerRow = 8;
inline constexpr int kSheetFirstChar = 32;
inline constexpr int kSheetGlyphCount = 96;  // 32..127
inline constexpr char kSheetInk = '#';

// kSheetGlyphCount / kSheetGlyphsPerRow blocks of kSheetGlyphHeight strings; each string is
// kSheetGlyphsPerRow glyph rows of kSheetGlyphWidth characters ('#' ink, '.' empty) separated
// by single spaces.
std::span<const char* const> fallback_font_sheet();

}  // namespace nq

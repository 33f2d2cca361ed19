// The status bar's big 24x24 digits (num_* white, anum_* red), as Quake lays them out: right-
// aligned in a field of `digits` places, 24 virtual pixels apart; a value with more
// characters than places shows only its last ones ("-100" in 3 places reads "100").
#pragma once

#include <cstdint>
#include <span>

#include "hud/hud_canvas.h"

namespace nq {

inline constexpr int kBigDigitWidth = 24;
inline constexpr int kStatusBarMaxValue = 999;  // the status bar shows at most 999

// The characters ('0'..'9', '-') shown for `value` in `digits` places; returns how many of
// `out` it filled (at most `digits`, at most out.size()).
size_t big_number_characters(int64_t value, int digits, std::span<char> out);

// Draws `value` with its field's left edge at (x, y) in `colour` (kWhiteNumbers, kRedNumbers).
void draw_big_number(const HudCanvas& canvas, float x, float y, int64_t value, int digits,
                     int colour);

}  // namespace nq

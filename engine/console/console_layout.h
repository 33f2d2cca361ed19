// Where the console puts things on a screen of a given size: the glyph scale and cell size,
// the text width in columns, and the rows of the console area. Pure arithmetic, shared by the
// text wrapping and the drawer so both agree.
#pragma once

#include <cstddef>

namespace nq {

inline constexpr int kGlyphPixels = 8;  // conchars cells are 8x8
inline constexpr int kMaxConsoleScale = 16;
// Quake's console was laid out for 640x480 (80 columns); larger screens scale it up whole.
inline constexpr int kReferenceScreenWidth = 640;
inline constexpr int kReferenceScreenHeight = 480;

struct ConsoleLayout {
    int screen_width = 0;  // pixels
    int screen_height = 0;
    int scale = 1;  // whole multiple of the 8x8 font
    int cell = kGlyphPixels;
    size_t columns = 1;  // text width in characters, one cell of margin on each side

    // Top of the input line for a console `height` pixels tall, and the top of the newest
    // text row above it (half a cell of gap in between).
    int input_row_top(int height) const { return height - 2 * cell; }
    int newest_text_row_top(int height) const { return input_row_top(height) - cell - cell / 2; }
    // Rows of scrollback text that fit above the input line of a console `height` tall.
    int text_rows(int height) const;
};

// `requested_scale` 0 (or less) picks the largest scale at which a 640x480 console still fits.
ConsoleLayout make_console_layout(int screen_width, int screen_height, int requested_scale);

}  // namespace nq

#include "console/console_layout.h"

#include <algorithm>

namespace nq {

int ConsoleLayout::text_rows(int height) const {
    int top = newest_text_row_top(height);
    return top < 0 ? 0 : top / cell + 1;
}

ConsoleLayout make_console_layout(int screen_width, int screen_height, int requested_scale) {
    ConsoleLayout layout;
    layout.screen_width = std::max(screen_width, 0);
    layout.screen_height = std::max(screen_height, 0);
    int automatic = std::min(layout.screen_width / kReferenceScreenWidth,
                             layout.screen_height / kReferenceScreenHeight);
    int scale = requested_scale > 0 ? requested_scale : automatic;
    layout.scale = std::clamp(scale, 1, kMaxConsoleScale);
    layout.cell = kGlyphPixels * layout.scale;
    int columns = layout.screen_width / layout.cell - 2;
    layout.columns = static_cast<size_t>(std::max(columns, 1));
    return layout;
}

}  // namespace nq

#include "console/console_scene.h"

#include <algorithm>
#include <cmath>

namespace nq {
namespace {

constexpr size_t kMaxCenterLines = 32;
constexpr double kCenterTopFraction = 0.35;  // Quake: short messages start 35% down
constexpr size_t kShortCenterMessageLines = 4;
constexpr int kLongCenterMessageTop = 48;  // in 8-pixel-font pixels
constexpr int kScrollMarkerSpacing = 4;    // one '^' every 4 columns

constexpr char kPrompt = ']';

float px(int value) {
    return static_cast<float>(value);
}

bool cursor_visible(double now) {
    return (static_cast<long long>(std::floor(now * kCursorBlinksPerSecond)) & 1) == 0;
}

}  // namespace

size_t ConsoleScene::notify_rows(const Console& console,
                                 std::array<std::string_view, kNotifyRows>& out) const {
    return console.text().notify_rows(console.now(), console.notify_seconds(), out);
}

bool ConsoleScene::center_print_showing(const Console& console) const {
    return console.center().visible(console.now(), console.center_seconds());
}

bool ConsoleScene::has_content(const Console& console) const {
    if (console.height_pixels() > 0) return true;
    std::array<std::string_view, kNotifyRows> rows;
    return notify_rows(console, rows) > 0 || center_print_showing(console);
}

std::array<float, 4> ConsoleScene::background_rect(const Console& console) const {
    const ConsoleLayout& layout = console.layout();
    int height = console.height_pixels();
    // A full-screen picture whose bottom edge follows the console's bottom edge.
    return {0.0f, px(height - layout.screen_height), px(layout.screen_width),
            px(layout.screen_height)};
}

void ConsoleScene::build(const Console& console, QuadBatch& batch, bool solid_background) {
    if (console.height_pixels() > 0) {
        build_panel(console, batch, solid_background);
        return;
    }
    build_notify(console, batch);
    build_center_print(console, batch);
}

void ConsoleScene::build_panel(const Console& console, QuadBatch& batch, bool solid_background) {
    const ConsoleLayout& layout = console.layout();
    int height = console.height_pixels();
    if (solid_background) {
        batch.solid(0, 0, px(layout.screen_width), px(height), style_.background);
    }
    int border = std::min(layout.scale, height);
    batch.solid(0, px(height - border), px(layout.screen_width), px(border), style_.border);
    build_scrollback(console, batch, height);
    build_input_line(console, batch, height);
}

void ConsoleScene::build_scrollback(const Console& console, QuadBatch& batch, int height) {
    const ConsoleLayout& layout = console.layout();
    int slots = layout.text_rows(height);
    if (slots <= 0) return;
    int top = layout.newest_text_row_top(height);
    float cell = px(layout.cell);
    if (console.text().scroll_rows() > 0) {  // the bottom slot says "there is more below"
        for (size_t column = 0; column < layout.columns; column += kScrollMarkerSpacing) {
            batch.glyph('^', cell * px(static_cast<int>(column) + 1), px(top), cell, style_.text);
        }
        top -= layout.cell;
        --slots;
    }
    if (rows_.size() < static_cast<size_t>(slots)) rows_.resize(static_cast<size_t>(slots));
    size_t count = console.text().visible_rows(std::span(rows_).first(static_cast<size_t>(slots)));
    for (size_t i = 0; i < count; ++i) {
        batch.text(rows_[i], cell, px(top - static_cast<int>(i) * layout.cell), cell, style_.text);
    }
}

void ConsoleScene::build_input_line(const Console& console, QuadBatch& batch, int height) {
    const ConsoleLayout& layout = console.layout();
    const std::string& text = console.input().line().text();
    float cell = px(layout.cell);
    float top = px(layout.input_row_top(height));
    auto column_x = [&](size_t column) { return cell * px(static_cast<int>(column) + 1); };

    // The row is the prompt and the text, scrolled sideways so the cursor stays on screen.
    size_t cursor_column = console.input().line().cursor() + 1;  // past the prompt
    size_t first = cursor_column >= layout.columns ? cursor_column + 1 - layout.columns : 0;
    for (size_t column = first; column <= text.size() && column < first + layout.columns;
         ++column) {
        char c = column == 0 ? kPrompt : text[column - 1];
        if (c != ' ')
            batch.glyph(static_cast<uint8_t>(c), column_x(column - first), top, cell, style_.text);
    }
    if (cursor_visible(console.now())) {
        batch.solid(column_x(cursor_column - first), top, cell, cell, style_.cursor);
    }
}

void ConsoleScene::build_notify(const Console& console, QuadBatch& batch) {
    std::array<std::string_view, kNotifyRows> rows;
    size_t count = notify_rows(console, rows);
    float cell = px(console.layout().cell);
    for (size_t i = 0; i < count; ++i) {  // oldest at the top
        batch.text(rows[count - 1 - i], cell, cell * px(static_cast<int>(i)), cell, style_.text);
    }
}

void ConsoleScene::build_center_print(const Console& console, QuadBatch& batch) {
    if (!center_print_showing(console)) return;
    const ConsoleLayout& layout = console.layout();
    std::array<std::string_view, kMaxCenterLines> lines;
    size_t count = console.center().lines(lines);
    int y = console.center().line_count() <= kShortCenterMessageLines
                ? static_cast<int>(layout.screen_height * kCenterTopFraction)
                : kLongCenterMessageTop * layout.scale;
    for (size_t i = 0; i < count; ++i, y += layout.cell) {
        int width = static_cast<int>(lines[i].size()) * layout.cell;
        batch.text(lines[i], px((layout.screen_width - width) / 2), px(y), px(layout.cell),
                   style_.text);
    }
}

}  // namespace nq

// The console's scrollback: a fixed-capacity ring of printed lines (the oldest drop when it is
// full), wrapped into screen rows at the console's width when read, so a resize re-wraps
// everything. Also the "notify" rows: recent lines shown at the top of the screen while the
// console is closed.
//
// Bytes are kept raw: a byte with bit 7 set is drawn from the alternate (gold/red) half of the
// conchars font. As in Quake, a print that starts with byte 1 or 2 is coloured that way
// whole (the marker byte itself is dropped).
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace nq {

inline constexpr size_t kDefaultConsoleLines = 1024;
// A longer line continues as a new line: bounds the memory one runaway print can take.
inline constexpr size_t kMaxConsoleLineBytes = 4096;
inline constexpr size_t kDefaultConsoleColumns = 78;  // Quake's 640-pixel console

class ConsoleText {
  public:
    explicit ConsoleText(size_t capacity_lines = kDefaultConsoleLines);

    // Appends text; '\n' ends a line. `now` (seconds) stamps lines for the notify area.
    void print(std::string_view text, double now);
    void clear();
    // Lines printed so far no longer show in the notify area (the console was toggled).
    void clear_notify();

    size_t capacity() const { return lines_.size(); }
    size_t line_count() const { return count_; }
    // age 0 is the newest line (possibly still unterminated); age < line_count().
    std::string_view line(size_t age) const { return slot(age).text; }
    double line_time(size_t age) const { return slot(age).time; }

    // Wrap width in characters (at least 1). Resets the scrollback to the bottom.
    void set_columns(size_t columns);
    size_t columns() const { return columns_; }
    // Wrapped rows of every stored line.
    size_t total_rows() const;

    // Scrollback, in rows above the newest; kept within [0, total_rows() - 1].
    void scroll(long delta_rows);  // positive: back in time
    void scroll_to_top();
    void scroll_to_bottom() { scroll_ = 0; }
    size_t scroll_rows() const { return scroll_; }

    // Fills `out` with the rows to show, newest first, starting `scroll_rows()` rows above the
    // newest; returns how many were filled. Views stay valid until the next print or clear.
    size_t visible_rows(std::span<std::string_view> out) const;
    // The newest rows of lines started within `seconds` before `now`, newest first, at most
    // out.size() of them (Quake shows 4).
    size_t notify_rows(double now, double seconds, std::span<std::string_view> out) const;

  private:
    struct Line {
        std::string text;
        double time = 0;
    };

    const Line& slot(size_t age) const;
    Line& begin_line(double now);
    void append(char c, double now);
    // Writes the rows of `text` newest-first into out[filled..], skipping `skip` of them
    // first; returns the new fill count and decrements `skip` by the rows it skipped.
    size_t put_rows(std::string_view text, size_t& skip, std::span<std::string_view> out,
                    size_t filled) const;

    std::vector<Line> lines_;  // ring; lines reuse their string capacity once it wraps
    size_t newest_ = 0;        // index of the newest line when count_ > 0
    size_t count_ = 0;
    bool line_open_ = false;  // the newest line still takes text (no '\n' seen yet)
    size_t columns_ = kDefaultConsoleColumns;
    size_t scroll_ = 0;
};

}  // namespace nq

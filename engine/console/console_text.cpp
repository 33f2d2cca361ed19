#include "console/console_text.h"

#include <algorithm>

#include "console/text_wrap.h"

namespace nq {
namespace {

constexpr unsigned char kColourBit = 0x80;
// Quake's convention for a whole coloured message: 1 (with a chat beep) or 2 (silent).
bool is_colour_marker(char c) {
    return c == 1 || c == 2;
}

}  // namespace

ConsoleText::ConsoleText(size_t capacity_lines) : lines_(std::max<size_t>(capacity_lines, 1)) {}

const ConsoleText::Line& ConsoleText::slot(size_t age) const {
    return lines_[(newest_ + lines_.size() - age) % lines_.size()];
}

ConsoleText::Line& ConsoleText::begin_line(double now) {
    if (count_ > 0) newest_ = (newest_ + 1) % lines_.size();
    count_ = std::min(count_ + 1, lines_.size());
    Line& line = lines_[newest_];
    line.text.clear();  // keeps its capacity: a full ring prints without allocating
    line.time = now;
    line_open_ = true;
    return line;
}

void ConsoleText::append(char c, double now) {
    if (c == '\r') return;
    if (c == '\n') {
        if (!line_open_) begin_line(now);
        line_open_ = false;
        return;
    }
    if (c == '\t') c = ' ';
    Line& line = line_open_ ? lines_[newest_] : begin_line(now);
    if (line.text.size() >= kMaxConsoleLineBytes) {
        begin_line(now).text.push_back(c);
        return;
    }
    line.text.push_back(c);
}

void ConsoleText::print(std::string_view text, double now) {
    unsigned char mask = 0;
    if (!text.empty() && is_colour_marker(text.front())) {
        mask = kColourBit;
        text.remove_prefix(1);
    }
    for (char c : text) {
        append(c == '\n' ? c : static_cast<char>(static_cast<unsigned char>(c) | mask), now);
    }
}

void ConsoleText::clear() {
    for (Line& line : lines_) line.text.clear();
    count_ = 0;
    newest_ = 0;
    line_open_ = false;
    scroll_ = 0;
}

void ConsoleText::clear_notify() {
    for (Line& line : lines_) line.time = -1e300;
}

void ConsoleText::set_columns(size_t columns) {
    columns_ = std::max<size_t>(columns, 1);
    scroll_ = 0;
}

size_t ConsoleText::total_rows() const {
    size_t rows = 0;
    for (size_t age = 0; age < count_; ++age) rows += wrapped_row_count(line(age), columns_);
    return rows;
}

void ConsoleText::scroll(long delta_rows) {
    long total = static_cast<long>(total_rows());
    long target = static_cast<long>(scroll_) + delta_rows;
    scroll_ = static_cast<size_t>(std::clamp(target, 0L, std::max(total - 1, 0L)));
}

void ConsoleText::scroll_to_top() {
    size_t total = total_rows();
    scroll_ = total > 0 ? total - 1 : 0;
}

size_t ConsoleText::put_rows(std::string_view text, size_t& skip, std::span<std::string_view> out,
                             size_t filled) const {
    size_t rows = wrapped_row_count(text, columns_);
    if (skip >= rows) {
        skip -= rows;
        return filled;
    }
    size_t shown = rows - skip;  // the first `shown` rows of the line, in reverse
    WrappedRow row = wrap_row(text, 0, columns_);
    for (size_t i = 0; i < shown; ++i, row = wrap_row(text, row.next, columns_)) {
        size_t position = filled + (shown - 1 - i);
        if (position < out.size()) out[position] = text.substr(row.begin, row.end - row.begin);
    }
    skip = 0;
    return std::min(out.size(), filled + shown);
}

size_t ConsoleText::visible_rows(std::span<std::string_view> out) const {
    size_t skip = scroll_;
    size_t filled = 0;
    for (size_t age = 0; age < count_ && filled < out.size(); ++age) {
        filled = put_rows(line(age), skip, out, filled);
    }
    return filled;
}

size_t ConsoleText::notify_rows(double now, double seconds, std::span<std::string_view> out) const {
    size_t skip = 0;
    size_t filled = 0;
    for (size_t age = 0; age < count_ && filled < out.size(); ++age) {
        if (!(line_time(age) > now - seconds)) break;  // older lines are older still
        filled = put_rows(line(age), skip, out, filled);
    }
    return filled;
}

}  // namespace nq

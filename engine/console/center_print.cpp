#include "console/center_print.h"

#include <algorithm>

namespace nq {
namespace {

// Calls `emit` for each line: pieces between '\n', cut every kCenterPrintLineWidth bytes. A
// trailing '\n' adds no empty line (messages from the server usually end with one).
template <class Emit>
void for_each_line(std::string_view text, Emit&& emit) {
    while (!text.empty()) {
        size_t end = std::min({text.find('\n'), text.size(), kCenterPrintLineWidth});
        if (!emit(text.substr(0, end))) return;
        text.remove_prefix(end);
        if (!text.empty() && text.front() == '\n') text.remove_prefix(1);
    }
}

}  // namespace

void CenterPrint::show(std::string_view text, double now) {
    text_.assign(text);
    shown_at_ = now;
}

bool CenterPrint::visible(double now, double seconds) const {
    return !text_.empty() && now >= shown_at_ && now < shown_at_ + seconds;
}

size_t CenterPrint::line_count() const {
    size_t count = 0;
    for_each_line(text_, [&](std::string_view) { return ++count, true; });
    return count;
}

size_t CenterPrint::lines(std::span<std::string_view> out) const {
    size_t filled = 0;
    for_each_line(text_, [&](std::string_view line) {
        if (filled == out.size()) return false;
        out[filled++] = line;
        return true;
    });
    return filled;
}

}  // namespace nq

#include "console/line_editor.h"

#include <algorithm>

namespace nq {
namespace {

bool is_printable_ascii(char c) {
    return c >= ' ' && c <= '~';
}

}  // namespace

void LineEditor::insert(std::string_view text) {
    for (char c : text) {
        if (!is_printable_ascii(c) || text_.size() >= kMaxInputLineBytes) continue;
        text_.insert(text_.begin() + static_cast<std::ptrdiff_t>(cursor_), c);
        ++cursor_;
    }
}

void LineEditor::move_left() {
    if (cursor_ > 0) --cursor_;
}

void LineEditor::move_right() {
    if (cursor_ < text_.size()) ++cursor_;
}

void LineEditor::backspace() {
    if (cursor_ == 0) return;
    text_.erase(--cursor_, 1);
}

void LineEditor::erase() {
    if (cursor_ < text_.size()) text_.erase(cursor_, 1);
}

void LineEditor::clear() {
    text_.clear();
    cursor_ = 0;
}

void LineEditor::set(std::string_view text, size_t cursor) {
    text_.assign(text.substr(0, kMaxInputLineBytes));
    cursor_ = std::min(cursor, text_.size());
}

}  // namespace nq

// The console's input line: printable ASCII text with a cursor that can sit anywhere in it.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace nq {

// Quake's command line held 256 bytes with its terminator.
inline constexpr size_t kMaxInputLineBytes = 255;

class LineEditor {
  public:
    // Inserts at the cursor and moves the cursor past the text. Bytes outside printable ASCII
    // (control bytes, UTF-8 sequences) are skipped; text beyond kMaxInputLineBytes is dropped.
    void insert(std::string_view text);
    void move_left();
    void move_right();
    void move_home() { cursor_ = 0; }
    void move_end() { cursor_ = text_.size(); }
    void backspace();  // deletes before the cursor
    void erase();      // deletes at the cursor (DEL)
    void clear();
    // Replaces the whole text (clipped to the limit), cursor at `cursor` (clamped to the end).
    void set(std::string_view text, size_t cursor = std::string_view::npos);

    const std::string& text() const { return text_; }
    size_t cursor() const { return cursor_; }

  private:
    std::string text_;
    size_t cursor_ = 0;
};

}  // namespace nq

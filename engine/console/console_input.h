// Keys and typed text while the console is open: line editing, history, TAB completion,
// scrollback, and ENTER, which echoes "]line" and sends the line to the command buffer.
#pragma once

#include <string_view>

#include "console/console_text.h"
#include "console/input_history.h"
#include "console/line_editor.h"
#include "host/command_system.h"

namespace nq {

// Rows one PGUP / PGDN moves the scrollback; the mouse wheel moves a third of that.
inline constexpr long kPageScrollRows = 6;
inline constexpr long kWheelScrollRows = 2;

class ConsoleInput {
  public:
    ConsoleInput(CommandSystem& commands, ConsoleText& text);

    // A console key (console_keys.h) went down or auto-repeated. Returns false when the key
    // means nothing to the input line.
    bool key_down(std::string_view key);
    void key_up(std::string_view key);
    // A Text event: inserted at the cursor (the console key's own character is dropped).
    void text_input(std::string_view text);

    // Runs the line: echo, history, command buffer, back to the bottom of the scrollback.
    void submit();
    void complete();

    const LineEditor& line() const { return line_; }
    LineEditor& line() { return line_; }
    const InputHistory& history() const { return history_; }

  private:
    bool edit_key(std::string_view key);
    bool history_key(std::string_view key);
    bool scroll_key(std::string_view key);

    CommandSystem& commands_;
    ConsoleText& text_;
    LineEditor line_;
    InputHistory history_;
    bool ctrl_held_ = false;
};

}  // namespace nq

#include "console/console_input.h"

#include <optional>
#include <string>

#include "console/tab_completion.h"

namespace nq {

ConsoleInput::ConsoleInput(CommandSystem& commands, ConsoleText& text)
    : commands_(commands), text_(text) {}

bool ConsoleInput::key_down(std::string_view key) {
    if (key == "CTRL") {
        ctrl_held_ = true;
        return true;
    }
    if (key == "ENTER" || key == "KP_ENTER") {
        submit();
        return true;
    }
    if (key == "TAB") {
        complete();
        return true;
    }
    return edit_key(key) || history_key(key) || scroll_key(key);
}

void ConsoleInput::key_up(std::string_view key) {
    if (key == "CTRL") ctrl_held_ = false;
}

bool ConsoleInput::edit_key(std::string_view key) {
    if (ctrl_held_ && (key == "HOME" || key == "END")) return false;  // scrollback keys
    if (key == "LEFTARROW") {
        line_.move_left();
    } else if (key == "RIGHTARROW") {
        line_.move_right();
    } else if (key == "HOME") {
        line_.move_home();
    } else if (key == "END") {
        line_.move_end();
    } else if (key == "BACKSPACE") {
        line_.backspace();
    } else if (key == "DEL") {
        line_.erase();
    } else {
        return false;
    }
    return true;
}

bool ConsoleInput::history_key(std::string_view key) {
    std::optional<std::string_view> recalled;
    if (key == "UPARROW") {
        recalled = history_.older(line_.text());
    } else if (key == "DOWNARROW") {
        recalled = history_.newer();
    } else {
        return false;
    }
    if (recalled) line_.set(*recalled);
    return true;
}

bool ConsoleInput::scroll_key(std::string_view key) {
    if (key == "PGUP") {
        text_.scroll(kPageScrollRows);
    } else if (key == "PGDN") {
        text_.scroll(-kPageScrollRows);
    } else if (key == "MWHEELUP") {
        text_.scroll(kWheelScrollRows);
    } else if (key == "MWHEELDOWN") {
        text_.scroll(-kWheelScrollRows);
    } else if (key == "HOME") {  // with CTRL
        text_.scroll_to_top();
    } else if (key == "END") {
        text_.scroll_to_bottom();
    } else {
        return false;
    }
    return true;
}

void ConsoleInput::text_input(std::string_view text) {
    for (char c : text) {
        if (c == '`' || c == '~') continue;  // the console key types nothing
        line_.insert(std::string_view(&c, 1));
    }
}

void ConsoleInput::submit() {
    const std::string& line = line_.text();
    commands_.print("]" + line + "\n");
    commands_.add_text(line + "\n");
    history_.add(line);
    line_.clear();
    text_.scroll_to_bottom();
}

void ConsoleInput::complete() {
    CompletionResult result = complete_command(commands_, line_.text(), line_.cursor());
    if (result.candidates.size() > 1) {
        std::string listing = "]" + line_.text() + "\n";
        for (const std::string& name : result.candidates) listing += "  " + name + "\n";
        commands_.print(listing);
    }
    line_.set(result.line, result.cursor);
}

}  // namespace nq

#include "console/console_keys.h"

#include <array>

namespace nq {
namespace {

constexpr std::array<std::string_view, 20> kEditingKeys = {
    "ENTER", "KP_ENTER",  "TAB",   "BACKSPACE", "DEL",        "INS",       "HOME",
    "END",   "PGUP",      "PGDN",  "LEFTARROW", "RIGHTARROW", "UPARROW",   "DOWNARROW",
    "SPACE", "SEMICOLON", "SHIFT", "CTRL",      "MWHEELUP",   "MWHEELDOWN"};

}  // namespace

bool is_console_key(std::string_view key) {
    // Every printable character key types into the line (the text arrives as a Text event).
    if (key.size() == 1) return key[0] > ' ' && key[0] < 127;
    for (std::string_view editing : kEditingKeys) {
        if (key == editing) return true;
    }
    return false;
}

}  // namespace nq

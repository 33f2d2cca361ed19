#include "host/key_names.h"

#include "host/text_util.h"

namespace nq {
namespace {

void add_numbered(std::vector<std::string>& out, std::string_view stem, int count) {
    for (int i = 1; i <= count; ++i) out.push_back(std::string(stem) + std::to_string(i));
}

std::vector<std::string> build_named_keys() {
    std::vector<std::string> keys = {
        "TAB",        "ENTER", "ESCAPE", "SPACE", "BACKSPACE", "UPARROW",  "DOWNARROW", "LEFTARROW",
        "RIGHTARROW", "ALT",   "CTRL",   "SHIFT", "CAPSLOCK",  "INS",      "DEL",       "PGDN",
        "PGUP",       "HOME",  "END",    "PAUSE", "SEMICOLON", "MWHEELUP", "MWHEELDOWN"};
    add_numbered(keys, "F", 12);
    add_numbered(keys, "MOUSE", 8);
    for (const char* kp : {"KP_HOME", "KP_UPARROW", "KP_PGUP", "KP_LEFTARROW", "KP_5",
                           "KP_RIGHTARROW", "KP_END", "KP_DOWNARROW", "KP_PGDN", "KP_ENTER",
                           "KP_INS", "KP_DEL", "KP_SLASH", "KP_STAR", "KP_MINUS", "KP_PLUS"}) {
        keys.push_back(kp);
    }
    add_numbered(keys, "JOY", 4);
    add_numbered(keys, "AUX", 32);
    return keys;
}

std::optional<std::string> single_character_key(char c) {
    if (c == ' ') return "SPACE";
    if (c == ';') return "SEMICOLON";
    if (c == '~') return "`";
    auto u = static_cast<unsigned char>(c);
    if (u <= ' ' || u >= 127 || c == '"') return std::nullopt;
    return to_lower_ascii(std::string_view(&c, 1));
}

}  // namespace

const std::vector<std::string>& named_keys() {
    static const std::vector<std::string> keys = build_named_keys();
    return keys;
}

std::optional<std::string> canonical_key_name(std::string_view name) {
    if (name.size() == 1) return single_character_key(name[0]);
    if (iequals(name, "BACKQUOTE") || iequals(name, "TILDE")) return "`";
    for (const std::string& key : named_keys()) {
        if (iequals(name, key)) return key;
    }
    return std::nullopt;
}

}  // namespace nq

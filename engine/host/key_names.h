// Names of bindable keys, as written in `bind` commands and config.cfg.
//
// Canonical forms: letters are lower case ("a"), digits and punctuation are the character
// itself ("1", "[", "`"), every other key is an upper-case name ("ESCAPE", "F1", "UPARROW",
// "MOUSE1"). Input is case-insensitive, and a few other spellings are accepted: "~", "TILDE"
// and "BACKQUOTE" are the console key "`" (one physical key); ";" is "SEMICOLON" and " " is
// "SPACE" (';' would otherwise separate commands). '"' cannot be bound.
// The SDL key mapping translates physical keys to these canonical names.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace nq {

// The canonical name of `name`, or nullopt when it is no key.
std::optional<std::string> canonical_key_name(std::string_view name);

// Every canonical multi-character key name, in a fixed documentation order.
const std::vector<std::string>& named_keys();

}  // namespace nq

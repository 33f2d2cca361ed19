// ASCII text helpers shared by the host core: Quake names are case-insensitive, ASCII only.
#pragma once

#include <string>
#include <string_view>

namespace nq {

std::string to_lower_ascii(std::string_view text);
bool iequals(std::string_view a, std::string_view b);
bool istarts_with(std::string_view text, std::string_view prefix);

// Whitespace inside a command: every control byte and space, except '\n' (a separator).
bool is_command_space(char c);

// A valid cvar, command, alias name: 1..64 printable ASCII bytes without '"' or ';', not
// starting with "//" (those would be read back as a string, a separator or a comment).
bool is_valid_name(std::string_view name);

// "1 cvar", "3 cvars".
std::string count_noun(size_t count, std::string_view singular);

}  // namespace nq

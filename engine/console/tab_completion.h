// TAB completion of the command name being typed: over commands, aliases and cvars, matched
// case-insensitively by prefix. One match completes (with a space after it); several complete
// as far as they agree and are listed.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "host/command_system.h"

namespace nq {

// Every command, alias and cvar name starting with `prefix`, sorted case-insensitively, each
// name once.
std::vector<std::string> completion_candidates(const CommandSystem& commands,
                                               std::string_view prefix);

// The longest prefix every name shares, compared case-insensitively, spelled as in the first.
std::string common_prefix(const std::vector<std::string>& names);

struct CompletionResult {
    std::string line;  // the line after completion (unchanged when nothing matched)
    size_t cursor = 0;
    std::vector<std::string> candidates;  // every match; more than one means ambiguous
};

// Completes the word before `cursor` when it is the command name of its command (the first
// word of the line or after a ';', not inside quotes). An empty word completes nothing.
CompletionResult complete_command(const CommandSystem& commands, std::string_view line,
                                  size_t cursor);

}  // namespace nq

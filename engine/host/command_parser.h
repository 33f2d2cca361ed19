// The Quake command-text tokenizer.
//
// Commands are separated by newlines and by ';' outside quotes. Tokens are separated by
// whitespace (any byte <= ' '). "Quoted strings" are one token without their quotes, may be
// empty, may hold ';' and spaces, and end at the closing quote or the end of the line. "//" at
// the start of a token begins a comment that runs to the end of the line (';' included); inside
// a word (http://x) or inside quotes it is plain text. There are no escape sequences.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "host/command_args.h"

namespace nq {

struct ParsedCommand {
    CommandArgs args;     // empty for a blank, comment-only or ";;" command
    size_t consumed = 0;  // bytes used from the text, separator included; > 0 unless text is empty
};

// Parses the first command in `text`.
ParsedCommand parse_next_command(std::string_view text);

// Every non-empty command in `text`, in order.
std::vector<CommandArgs> parse_commands(std::string_view text);

// `token` as command text that reads back as exactly that one token: quoted when it is empty or
// holds whitespace, ';' or starts a comment; as is otherwise. Line breaks become spaces (they
// would end the command). A token holding '"' is returned unquoted, since no quoting can
// protect it: it is then not guaranteed to read back as one token.
std::string quote_if_needed(std::string_view token);

}  // namespace nq

// Turning an alias invocation into the text that runs.
//
// In the body, $1..$9 become the invocation's arguments (empty when missing), $* all of them
// as typed (quotes included), $0 the alias name and $$ a single '$'; any other '$' is kept.
// Arguments are substituted as plain text, without quotes: write "$1" in the body to keep an
// argument with spaces together. A body without any $ reference gets the invocation's
// arguments appended, so `alias fwd "+forward"` ... `fwd x` runs "+forward x" (on its last
// command when the body holds several).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "host/command_args.h"

namespace nq {

// nullopt when the expansion would exceed `max_bytes`.
std::optional<std::string> expand_alias(std::string_view body, const CommandArgs& invocation,
                                        size_t max_bytes);

}  // namespace nq

// Console commands for key bindings: bind, unbind, unbindall, bindlist.
#pragma once

#include "host/command_system.h"
#include "host/key_bindings.h"

namespace nq {

void register_bind_commands(CommandSystem& commands, KeyBindings& bindings);

// The command `bind` stores for these arguments: one quoted string, or the raw rest of the
// line (quotes kept) from the third token on. Shared with the config writer, which checks that
// what it writes reads back the same.
std::string bound_command(const CommandArgs& args);

}  // namespace nq

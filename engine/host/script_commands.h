// Console commands for scripting: echo, alias, unalias, exec, wait, cmdlist.
#pragma once

#include <string_view>

#include "host/command_system.h"

namespace nq {

void register_script_commands(CommandSystem& commands);

// exec refuses absolute paths and ".." components: scripts name files inside the game.
bool is_safe_script_path(std::string_view path);

}  // namespace nq

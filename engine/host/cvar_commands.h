// Console commands about cvars: set, seta, toggle, reset, cvarlist, and the Quake rule that a
// command named like a cvar shows it (no argument) or sets it (one argument).
#pragma once

#include "host/command_args.h"
#include "host/command_system.h"
#include "host/cvar_registry.h"

namespace nq {

void register_cvar_commands(CommandSystem& commands);

// `name` prints `"name" is "value"`; `name value` sets it as the user.
void show_or_set_cvar(CommandSystem& commands, Cvar& cvar, const CommandArgs& args);

// Prints why a user's change was refused or altered (nothing when it was taken as given).
void report_set_result(CommandSystem& commands, const Cvar& cvar, CvarSetResult result);

// One `cvarlist` line: 4 flag columns (A archive, R read-only, P plugin, U user-created), the
// name, the quoted value and " - description" when there is one.
std::string cvarlist_line(const Cvar& cvar);

}  // namespace nq

// config.cfg: the archived cvars and the key bindings, written as console commands that `exec`
// reads back. The output is sorted and deterministic (same state, same bytes):
//
//   // header comment
//   unbindall
//   bind "KEY" "command"       one per binding, by key name (byte order)
//   seta name "value"          one per archived, writable cvar, by lower-case name
//
// `seta` (not a bare `name "value"`) so that a plugin's cvar that is not registered when the
// config runs is created as an archived user cvar: its value survives sessions in which the
// plugin is not loaded. A value that no Quake syntax can carry (a '"' inside text with spaces,
// a line break) is left out with a comment saying so, rather than written so that it would
// read back as something else.
#pragma once

#include <string>

#include "host/cvar_registry.h"
#include "host/key_bindings.h"

namespace nq {

std::string config_text(const CvarRegistry& cvars, const KeyBindings& bindings);

// Writes config_text to `path`; returns "" on success, otherwise the reason.
std::string save_config(const std::string& path, const CvarRegistry& cvars,
                        const KeyBindings& bindings);

}  // namespace nq

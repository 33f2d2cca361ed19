// Spawning a level's entities from its entity lump, as Quake's ED_LoadFromFile does: the first
// entity fills the world edict, every other one a newly allocated edict; each key is assigned to
// the QuakeC field of that name (typed by the field's definition), entities the skill or
// deathmatch setting excludes are dropped, and the QuakeC function named by the classname runs
// with `self` set to the new edict.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "formats/entities.h"
#include "server/game_state.h"

namespace nq::server {

struct SpawnSettings {
    int skill = 1;
    bool deathmatch = false;
};

struct SpawnReport {
    int spawned = 0;                    // spawn functions run
    int inhibited = 0;                  // dropped by skill or deathmatch flags
    std::vector<std::string> warnings;  // unknown keys, missing spawn functions, ...
};

// Spawns every entity of `list`. False when QuakeC failed (the VM holds the error).
bool spawn_entities(GameState& game, const EntityList& list, const SpawnSettings& settings,
                    SpawnReport& report);

// Assigns `value` to the field named `key` of `edict` the way the entity lump does (Quake's
// "angle" becomes "angles"; keys starting with '_' are editor notes). False when the progs has no
// such field. Also used by saved games.
bool assign_field(vm::Vm& vm, uint32_t edict, std::string_view key, std::string_view value);
// The same for a global (a saved game's globals block, Quake's ED_ParseGlobals), found with
// find_saved_global. False when the progs has no such global.
bool assign_global(vm::Vm& vm, std::string_view key, std::string_view value);
// The global definition named `name`. A function's local may share the name of a global (both
// are in the global definitions): the one marked for saving wins. Null when there is none.
const vm::Def* find_saved_global(const vm::Progs& progs, std::string_view name);

// Quake's atof: the leading number of `text` (0 when there is none).
float leading_float(std::string_view text);

}  // namespace nq::server

// Restoring a parsed save onto a freshly spawned level: the part of Quake's Host_Loadgame_f
// after SV_SpawnServer. Values are assigned by name exactly as ED_ParseGlobals and ED_ParseEdict
// assign them; names the progs does not know are skipped with a developer warning, as Quake
// does, but a function or field value that names nothing fails the load, as it fails Quake's.
#include <algorithm>

#include "server/entity_spawner.h"
#include "server/savegame.h"

namespace nq::server {

namespace {

std::string problem(const LoadedGame& game, size_t offset, std::string message) {
    return Error{game.file_name, offset, std::move(message)}.to_string();
}

// What ED_ParseEpair refuses: a function or field value that names nothing in this progs.
std::string unresolved(const vm::Progs& progs, const vm::Def& def, const std::string& value) {
    if (def.def_type() == vm::DefType::function && !value.empty() &&
        progs.find_function(value) == 0) {
        return "'" + std::string(progs.string_at(def.name)) + "' names no function '" + value +
               "' of " + progs.name;
    }
    if (def.def_type() == vm::DefType::field && !progs.find_field(value)) {
        return "'" + std::string(progs.string_at(def.name)) + "' names no field '" + value +
               "' of " + progs.name;
    }
    return "";
}

std::string restore_globals(ServerLevel& level, const LoadedGame& game) {
    vm::Vm& vm = *level.vm;
    for (const SavedPair& pair : game.globals.pairs) {
        const vm::Def* def = pair.key.empty() ? nullptr : find_saved_global(vm.progs(), pair.key);
        if (!def) {
            level.host.debug_print("load: '" + pair.key + "' is not a global\n");
            continue;
        }
        if (std::string why = unresolved(vm.progs(), *def, pair.value); !why.empty()) {
            return problem(game, pair.offset, why);
        }
        assign_global(vm, pair.key, pair.value);
    }
    return "";
}

// One "key" "value" of an edict, with ED_ParseEdict's renames and skips.
std::string restore_pair(ServerLevel& level, const LoadedGame& game, uint32_t edict,
                         const SavedPair& pair) {
    vm::Vm& vm = *level.vm;
    std::string key = pair.key;
    while (!key.empty() && key.back() == ' ') key.pop_back();
    if (key.empty() || key.front() == '_') return "";  // editor notes
    std::string value = pair.value;
    if (key == "angle") {  // a yaw alone
        key = "angles";
        value = "0 " + value + " 0";
    } else if (key == "light") {
        key = "light_lev";
    }
    const vm::Def* def = vm.progs().find_field(key);
    if (!def) {
        level.host.debug_print("load: '" + key + "' is not a field (edict " +
                               std::to_string(edict) + ")\n");
        return "";
    }
    if (std::string why = unresolved(vm.progs(), *def, value); !why.empty()) {
        return problem(game, pair.offset, "edict " + std::to_string(edict) + ": " + why);
    }
    assign_field(vm, edict, key, value);
    return "";
}

std::string restore_edicts(ServerLevel& level, const LoadedGame& game) {
    vm::Vm& vm = *level.vm;
    const size_t count = game.edicts.size();
    if (count > vm.max_edicts()) {
        return problem(game, game.edicts[vm.max_edicts()].offset,
                       "more than " + std::to_string(vm.max_edicts()) + " edicts (max_edicts)");
    }
    for (uint32_t e = 0; e <= level.max_clients(); ++e) {
        if (game.edicts[e].pairs.empty()) {
            return problem(game, game.edicts[e].offset,
                           e == 0 ? "the world's edict is empty" : "the player's edict is empty");
        }
    }
    // What the map's own spawn made goes: edicts past the saved ones are left free.
    level.world.clear();
    for (uint32_t e = uint32_t(count); e < vm.num_edicts(); ++e) {
        vm.clear_edict(e);
        level.edicts.set_free(e, true);
    }
    vm.set_num_edicts(uint32_t(count));
    for (uint32_t e = 0; e < count; ++e) {
        vm.clear_edict(e);
        level.edicts.set_free(e, game.edicts[e].pairs.empty());
        for (const SavedPair& pair : game.edicts[e].pairs) {
            if (std::string why = restore_pair(level, game, e, pair); !why.empty()) return why;
        }
    }
    for (uint32_t e = 1; e < count; ++e) {
        if (!level.edicts.is_free(e)) level.world.link(e, false);
    }
    return "";
}

}  // namespace

std::string apply_savegame(ServerLevel& level, const LoadedGame& game) {
    if (game.map != level.map_name) {
        return problem(game, 0, "the save is of " + game.map + ", the level is " + level.map_name);
    }
    if (game.edicts.size() <= level.max_clients()) {
        return problem(game, 0, "the save holds no player edict");
    }
    for (size_t i = 0; i < level.lightstyles.size(); ++i) {
        level.lightstyles[i] = game.lightstyles[i].substr(0, 64);  // set_lightstyle's limit
    }
    level.game.time = game.time;
    if (std::string why = restore_globals(level, game); !why.empty()) return why;
    if (std::string why = restore_edicts(level, game); !why.empty()) return why;
    level.client.spawn_parms = game.spawn_parms;
    return "";
}

}  // namespace nq::server

#include "server/entity_spawner.h"

#include <charconv>
#include <cmath>

namespace nq::server {

namespace {

// Entity flags that keep an entity out of a skill level or deathmatch.
constexpr int kNotEasy = 256, kNotMedium = 512, kNotHard = 1024, kNotDeathmatch = 2048;

// The lump's "\n" becomes a newline (messages of trigger entities); other backslashes stay.
std::string unescape(std::string_view value) {
    std::string out;
    out.reserve(value.size());
    for (size_t i = 0; i < value.size(); ++i) {
        if (value[i] == '\\' && i + 1 < value.size()) {
            ++i;
            out.push_back(value[i] == 'n' ? '\n' : '\\');
        } else {
            out.push_back(value[i]);
        }
    }
    return out;
}

vm::Vec3f leading_vector(std::string_view text) {
    vm::Vec3f v{};
    for (float& c : v) {
        const size_t start = text.find_first_not_of(" \t");
        if (start == std::string_view::npos) break;
        text.remove_prefix(start);
        c = leading_float(text);
        const size_t end = text.find_first_of(" \t");
        if (end == std::string_view::npos) break;
        text.remove_prefix(end);
    }
    return v;
}

bool excluded(const vm::Vm& vm, const ProgsLayout& layout, uint32_t edict,
              const SpawnSettings& settings) {
    const int flags = int(vm.field_float(edict, layout.fields.spawnflags));
    if (settings.deathmatch) return (flags & kNotDeathmatch) != 0;
    if (settings.skill <= 0) return (flags & kNotEasy) != 0;
    if (settings.skill == 1) return (flags & kNotMedium) != 0;
    return (flags & kNotHard) != 0;
}

std::string describe(const Entity& entity) {
    std::string s = "entity at offset " + std::to_string(entity.offset);
    const std::string_view name = classname(entity);
    if (!name.empty()) s += " (" + std::string(name) + ")";
    return s;
}

}  // namespace

float leading_float(std::string_view text) {
    const size_t start = text.find_first_not_of(" \t\r\n");
    if (start == std::string_view::npos) return 0;
    text.remove_prefix(start);
    if (!text.empty() && text.front() == '+') text.remove_prefix(1);
    float value = 0;
    const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
    if (result.ec == std::errc::result_out_of_range) {
        return text.front() == '-' ? -INFINITY : INFINITY;
    }
    return result.ec == std::errc() ? value : 0.0f;
}

bool assign_field(vm::Vm& vm, uint32_t edict, std::string_view key, std::string_view value) {
    const vm::Def* def = vm.progs().find_field(key);
    if (!def) return false;
    const uint32_t ofs = def->offset;
    switch (def->def_type()) {
        case vm::DefType::string:
            vm.set_field_int(edict, ofs, vm.strings().make_level(unescape(value)));
            break;
        case vm::DefType::float_:
            vm.set_field_float(edict, ofs, leading_float(value));
            break;
        case vm::DefType::vector:
            vm.set_field_vector(edict, ofs, leading_vector(value));
            break;
        case vm::DefType::entity: {
            const float n = leading_float(value);
            const uint32_t e = n >= 0 && n < float(vm.max_edicts()) ? uint32_t(n) : 0;
            vm.set_field_int(edict, ofs, int32_t(vm.entity_value(e)));
            break;
        }
        case vm::DefType::field: {
            const vm::Def* field = vm.progs().find_field(value);
            vm.set_field_int(edict, ofs, field ? field->offset : 0);
            break;
        }
        case vm::DefType::function:
            vm.set_field_int(edict, ofs, vm.progs().find_function(value));
            break;
        default:
            break;
    }
    return true;
}

bool spawn_entities(GameState& game, const EntityList& list, const SpawnSettings& settings,
                    SpawnReport& report) {
    vm::Vm& vm = game.vm;
    const ProgsLayout& layout = game.layout;
    bool first = true;
    for (const Entity& entity : list.entities) {
        uint32_t edict = 0;
        if (!first) {
            const std::optional<uint32_t> e = game.edicts.alloc(vm, game.time);
            if (!e) {
                report.warnings.push_back("no free edict for " + describe(entity));
                break;
            }
            edict = *e;
        }
        first = false;
        for (const auto& [key, value] : entity.pairs) {
            if (key.empty() || key.front() == '_') continue;  // editor-only keys
            if (key == "angle") {                             // a yaw alone
                assign_field(vm, edict, "angles", "0 " + value + " 0");
                continue;
            }
            const std::string_view field = key == "light" ? "light_lev" : std::string_view(key);
            if (!assign_field(vm, edict, field, value)) {
                report.warnings.push_back("'" + key + "' is not a field (" + describe(entity) +
                                          ")");
            }
        }
        if (edict != 0 && excluded(vm, layout, edict, settings)) {
            game.edicts.free(vm, layout, edict, game.time);
            ++report.inhibited;
            continue;
        }
        const std::string_view name = classname(entity);
        const int32_t spawn = name.empty() ? 0 : vm.progs().find_function(name);
        if (spawn == 0 || vm.progs().functions[size_t(spawn)].builtin()) {
            report.warnings.push_back(name.empty() ? "no classname for " + describe(entity)
                                                   : "no spawn function for " + describe(entity));
            if (edict != 0) game.edicts.free(vm, layout, edict, game.time);
            continue;
        }
        vm.set_global_word(layout.globals.self, vm.entity_value(edict));
        if (!vm.execute(spawn)) return false;
        ++report.spawned;
    }
    return true;
}

}  // namespace nq::server

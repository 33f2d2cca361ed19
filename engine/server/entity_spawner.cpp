#include "server/entity_spawner.h"

#include <array>
#include <bit>
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

namespace {

// A value as the words its definition's type stores (none for types a map or save cannot set).
struct Words {
    std::array<uint32_t, 3> w{};
    uint32_t count = 0;
};

Words parse_value(vm::Vm& vm, vm::DefType type, std::string_view value) {
    auto word = [](float f) { return std::bit_cast<uint32_t>(f); };
    switch (type) {
        case vm::DefType::string:
            return {{uint32_t(vm.strings().make_level(unescape(value)))}, 1};
        case vm::DefType::float_:
            return {{word(leading_float(value))}, 1};
        case vm::DefType::vector: {
            const vm::Vec3f v = leading_vector(value);
            return {{word(v[0]), word(v[1]), word(v[2])}, 3};
        }
        case vm::DefType::entity: {
            const float n = leading_float(value);
            const uint32_t e = n >= 0 && n < float(vm.max_edicts()) ? uint32_t(n) : 0;
            return {{vm.entity_value(e)}, 1};
        }
        case vm::DefType::field: {
            const vm::Def* field = vm.progs().find_field(value);
            return {{field ? field->offset : 0u}, 1};
        }
        case vm::DefType::function:
            return {{uint32_t(vm.progs().find_function(value))}, 1};
        default:
            return {};
    }
}

}  // namespace

bool assign_field(vm::Vm& vm, uint32_t edict, std::string_view key, std::string_view value) {
    const vm::Def* def = vm.progs().find_field(key);
    if (!def) return false;
    const Words v = parse_value(vm, def->def_type(), value);
    for (uint32_t i = 0; i < v.count; ++i) {
        vm.set_field_int(edict, def->offset + i, int32_t(v.w[i]));
    }
    return true;
}

const vm::Def* find_saved_global(const vm::Progs& progs, std::string_view name) {
    const vm::Def* def = nullptr;
    for (const vm::Def& d : progs.global_defs) {
        if (progs.string_at(d.name) != name) continue;
        if (!def || (d.saved() && !def->saved())) def = &d;
    }
    return def;
}

bool assign_global(vm::Vm& vm, std::string_view key, std::string_view value) {
    const vm::Def* def = find_saved_global(vm.progs(), key);
    if (!def) return false;
    const Words v = parse_value(vm, def->def_type(), value);
    for (uint32_t i = 0; i < v.count; ++i) vm.set_global_word(def->offset + i, v.w[i]);
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

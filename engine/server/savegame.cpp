// Writing a save file: Quake's Host_Savegame_f, ED_WriteGlobals, ED_Write and
// PR_UglyValueString, byte for byte.
#include "server/savegame.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>

namespace nq::server {

namespace {

using vm::DefType;

std::string printf_float(double v) {
    char text[400];  // "%f" of the largest double is 316 characters
    std::snprintf(text, sizeof text, "%f", v);
    return text;
}

int clamped_int(float v) {
    return std::isfinite(v) ? int(std::clamp(v, -1e9f, 1e9f)) : 0;
}

// Quake's ED_FieldAtOfs: the first field definition at that offset (a vector before its _x).
std::string_view field_name_at(const vm::Progs& progs, uint32_t offset) {
    for (const vm::Def& d : progs.field_defs) {
        if (d.offset == offset) return progs.string_at(d.name);
    }
    return {};
}

// PR_UglyValueString: a value the way a save file holds it. `w` is the value's words.
std::string ugly_value(const vm::Vm& vm, uint16_t type, const std::array<uint32_t, 3>& w) {
    const vm::Progs& progs = vm.progs();
    auto as_float = [](uint32_t word) { return std::bit_cast<float>(word); };
    switch (static_cast<DefType>(type)) {
        case DefType::string:
            return std::string(vm.string_or_empty(int32_t(w[0])));
        case DefType::entity:
            return std::to_string(w[0] / vm.entity_value(1));
        case DefType::function:
            return std::string(progs.function_name(int32_t(w[0])));
        case DefType::field:
            return std::string(field_name_at(progs, w[0]));
        case DefType::void_:
            return "void";
        case DefType::float_:
            return printf_float(as_float(w[0]));
        case DefType::vector:
            return printf_float(as_float(w[0])) + " " + printf_float(as_float(w[1])) + " " +
                   printf_float(as_float(w[2]));
        default:
            return "bad type " + std::to_string(type);
    }
}

void write_pair(std::string& out, std::string_view name, const std::string& value) {
    out += '"';
    out += name;
    out += "\" \"";
    out += value;
    out += "\"\n";
}

// ED_WriteGlobals: the globals the compiler marked for saving, strings, floats and entities
// only (a vector global is saved through its _x, _y and _z floats).
void write_globals(std::string& out, const vm::Vm& vm) {
    out += "{\n";
    for (const vm::Def& def : vm.progs().global_defs) {
        const DefType type = def.def_type();
        if (!def.saved()) continue;
        if (type != DefType::string && type != DefType::float_ && type != DefType::entity) continue;
        const std::array<uint32_t, 3> w{vm.global_word(def.offset), 0, 0};
        write_pair(out, vm.progs().string_at(def.name), ugly_value(vm, uint16_t(type), w));
    }
    out += "}\n";
}

// ED_Write: every field but the vector components (Quake skips any name whose second-to-last
// character is '_') and those whose words are all zero.
void write_edict(std::string& out, const ServerLevel& level, uint32_t edict) {
    out += "{\n";
    if (level.edicts.is_free(edict)) {
        out += "}\n";
        return;
    }
    const vm::Vm& vm = *level.vm;
    const std::vector<vm::Def>& defs = vm.progs().field_defs;
    for (size_t i = 1; i < defs.size(); ++i) {
        const std::string_view name = vm.progs().string_at(defs[i].name);
        if (name.size() > 1 && name[name.size() - 2] == '_') continue;
        const uint16_t type = uint16_t(defs[i].type & ~vm::kDefSaveGlobal);
        if (type > uint16_t(DefType::pointer)) continue;
        const uint32_t words = type == uint16_t(DefType::vector) ? 3 : 1;
        std::array<uint32_t, 3> w{};
        for (uint32_t k = 0; k < words; ++k) {
            w[k] = uint32_t(vm.field_int(edict, defs[i].offset + k));
        }
        if (w == std::array<uint32_t, 3>{}) continue;
        write_pair(out, name, ugly_value(vm, type, w));
    }
    out += "}\n";
}

}  // namespace

std::string savegame_comment(const ServerLevel& level) {
    const vm::Vm& vm = *level.vm;
    std::string text(kSaveCommentLength, ' ');
    const std::string_view title = vm.string_or_empty(vm.field_int(0, level.layout.fields.message));
    text.replace(0, std::min<size_t>(title.size(), 22), title.substr(0, 22));
    std::replace_if(
        text.begin(), text.end(), [](char c) { return c == '\n' || c == '\r'; }, ' ');
    char kills[64];
    std::snprintf(kills, sizeof kills, "kills:%3i/%3i",
                  clamped_int(vm.global_float(level.layout.globals.killed_monsters)),
                  clamped_int(vm.global_float(level.layout.globals.total_monsters)));
    const std::string_view k(kills);
    text.replace(22, std::min(k.size(), kSaveCommentLength - 22),
                 k.substr(0, kSaveCommentLength - 22));
    return text;
}

std::string write_savegame(const ServerLevel& level, std::string_view comment, int skill) {
    std::string out = std::to_string(kSaveVersion) + "\n";
    std::string line(comment.substr(0, kSaveCommentLength));
    line.resize(kSaveCommentLength, ' ');
    for (char& c : line) {
        if (uint8_t(c) <= ' ') c = '_';
    }
    out += line + "\n";
    for (float parm : level.client.spawn_parms) out += printf_float(parm) + "\n";
    out += std::to_string(skill) + "\n";
    out += level.map_name + "\n";
    out += printf_float(level.game.time) + "\n";
    for (const std::string& style : level.lightstyles) out += (style.empty() ? "m" : style) + "\n";
    write_globals(out, *level.vm);
    for (uint32_t e = 0; e < level.vm->num_edicts(); ++e) write_edict(out, level, e);
    return out;
}

}  // namespace nq::server

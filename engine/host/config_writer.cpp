#include "host/config_writer.h"

#include <functional>
#include <optional>

#include "common/file_io.h"
#include "host/bind_commands.h"
#include "host/command_parser.h"

namespace nq {
namespace {

using ValueOf = std::function<std::string(const CommandArgs&)>;

// `head` followed by `value`, quoted if possible, else as is; only when the line reads back
// as exactly one command whose value (as the real command extracts it) is `value`.
std::optional<std::string> round_trip_line(const std::string& head, const std::string& value,
                                           const ValueOf& value_of) {
    for (const std::string& candidate : {head + " \"" + value + "\"", head + " " + value}) {
        std::vector<CommandArgs> parsed = parse_commands(candidate);
        if (parsed.size() == 1 && value_of(parsed[0]) == value) return candidate;
    }
    return std::nullopt;
}

void append_line(std::string& out, const std::string& head, const std::string& value,
                 const ValueOf& value_of, const std::string& what) {
    std::optional<std::string> line = round_trip_line(head, value, value_of);
    out += line ? *line : "// not saved: " + what + " cannot be written as a command";
    out += '\n';
}

void append_bindings(std::string& out, const KeyBindings& bindings) {
    out += "unbindall\n";
    for (const auto& [key, command] : bindings.all()) {
        append_line(out, "bind \"" + key + "\"", command, bound_command,
                    "the binding of key \"" + key + "\"");
    }
}

bool is_saved(const Cvar& cvar) {
    return cvar.has_flag(kCvarArchive) && !cvar.has_flag(kCvarReadOnly);
}

void append_cvars(std::string& out, const CvarRegistry& cvars) {
    // `seta` takes its value the way CommandArgs::value_from(2) reads it.
    ValueOf seta_value = [](const CommandArgs& args) { return args.value_from(2); };
    for (const Cvar* cvar : cvars.list()) {
        if (!is_saved(*cvar)) continue;
        append_line(out, "seta " + cvar->name(), cvar->string(), seta_value,
                    "the value of cvar \"" + cvar->name() + "\"");
    }
}

}  // namespace

std::string config_text(const CvarRegistry& cvars, const KeyBindings& bindings) {
    std::string out = "// Written by nprquake on exit. Put your own commands in autoexec.cfg.\n";
    append_bindings(out, bindings);
    append_cvars(out, cvars);
    return out;
}

std::string save_config(const std::string& path, const CvarRegistry& cvars,
                        const KeyBindings& bindings) {
    std::string text = config_text(cvars, bindings);
    return write_file(path, {reinterpret_cast<const uint8_t*>(text.data()), text.size()});
}

}  // namespace nq

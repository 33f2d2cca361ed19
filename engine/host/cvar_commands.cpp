#include "host/cvar_commands.h"

#include <algorithm>

#include "host/number_text.h"
#include "host/quoted.h"
#include "host/text_util.h"

namespace nq {
namespace {

void set_command(CommandSystem& commands, const CommandArgs& args, uint32_t extra_flags) {
    if (args.argc() < 3) {
        commands.print("usage: " + args.name() + " <cvar> <value>\n");
        return;
    }
    const std::string& name = args.argv(1);
    CvarSetResult result = commands.cvars().set_or_create(name, args.value_from(2), extra_flags);
    if (result == CvarSetResult::kInvalidName) {
        commands.print(args.name() + ": invalid cvar name " + quoted(name) + "\n");
        return;
    }
    report_set_result(commands, *commands.cvars().find(name), result);
}

Cvar* find_or_complain(CommandSystem& commands, const CommandArgs& args) {
    Cvar* cvar = commands.cvars().find(args.argv(1));
    if (!cvar) commands.print(args.name() + ": no cvar named " + quoted(args.argv(1)) + "\n");
    return cvar;
}

// `toggle x`: 0 <-> 1. `toggle x a b c`: the value after the current one, wrapping around
// (the first one when the current value is not in the list).
std::string toggled_value(const Cvar& cvar, const CommandArgs& args) {
    if (args.argc() <= 2) return cvar.value() != 0.0f ? "0" : "1";
    const auto& tokens = args.tokens();
    auto current = std::find(tokens.begin() + 2, tokens.end(), cvar.string());
    if (current == tokens.end() || current + 1 == tokens.end()) return tokens[2];
    return *(current + 1);
}

void toggle_command(CommandSystem& commands, const CommandArgs& args) {
    if (args.argc() < 2) {
        commands.print("usage: toggle <cvar> [value1 value2 ...]\n");
        return;
    }
    Cvar* cvar = find_or_complain(commands, args);
    if (!cvar) return;
    CvarSetResult result =
        commands.cvars().set(*cvar, toggled_value(*cvar, args), CvarSource::kUser);
    report_set_result(commands, *cvar, result);
}

void reset_command(CommandSystem& commands, const CommandArgs& args) {
    if (args.argc() < 2) {
        commands.print("usage: reset <cvar>\n");
        return;
    }
    Cvar* cvar = find_or_complain(commands, args);
    if (!cvar) return;
    report_set_result(commands, *cvar, commands.cvars().reset(*cvar, CvarSource::kUser));
}

void cvarlist_command(CommandSystem& commands, const CommandArgs& args) {
    const std::string& prefix = args.argv(1);
    std::vector<const Cvar*> cvars = commands.cvars().list(prefix);
    std::string text;
    for (const Cvar* cvar : cvars) text += cvarlist_line(*cvar) + "\n";
    text += count_noun(cvars.size(), "cvar");
    if (!prefix.empty()) text += " beginning with " + quoted(prefix);
    commands.print(text + "\n");
}

}  // namespace

void register_cvar_commands(CommandSystem& commands) {
    commands.add_command(
        "set", [&commands](const CommandArgs& a) { set_command(commands, a, 0); },
        "set <cvar> <value>: set a cvar, creating it when unknown");
    commands.add_command(
        "seta", [&commands](const CommandArgs& a) { set_command(commands, a, kCvarArchive); },
        "seta <cvar> <value>: set a cvar and save it to config.cfg");
    commands.add_command(
        "toggle", [&commands](const CommandArgs& a) { toggle_command(commands, a); },
        "toggle <cvar> [values...]: flip between 0 and 1, or cycle through the values");
    commands.add_command(
        "reset", [&commands](const CommandArgs& a) { reset_command(commands, a); },
        "reset <cvar>: restore a cvar's default value");
    commands.add_command(
        "cvarlist", [&commands](const CommandArgs& a) { cvarlist_command(commands, a); },
        "cvarlist [prefix]: list cvars with flags, values and descriptions");
}

void show_or_set_cvar(CommandSystem& commands, Cvar& cvar, const CommandArgs& args) {
    if (args.argc() < 2) {
        commands.print(quoted(cvar.name()) + " is " + quoted(cvar.string()) + "\n");
        return;
    }
    report_set_result(commands, cvar,
                      commands.cvars().set(cvar, args.value_from(1), CvarSource::kUser));
}

void report_set_result(CommandSystem& commands, const Cvar& cvar, CvarSetResult result) {
    std::string name = quoted(cvar.name());
    switch (result) {
        case CvarSetResult::kReadOnly:
            commands.print(name + " is read-only\n");
            break;
        case CvarSetResult::kNotNumeric:
            commands.print(name + " needs a number " + describe_range(cvar) + "; unchanged\n");
            break;
        case CvarSetResult::kClamped:
            commands.print(name + " clamped to " + cvar.string() + " (must be " +
                           describe_range(cvar) + ")\n");
            break;
        default:
            break;
    }
}

std::string cvarlist_line(const Cvar& cvar) {
    std::string line;
    line += cvar.has_flag(kCvarArchive) ? 'A' : ' ';
    line += cvar.has_flag(kCvarReadOnly) ? 'R' : ' ';
    line += cvar.has_flag(kCvarPlugin) ? 'P' : ' ';
    line += cvar.has_flag(kCvarUserCreated) ? 'U' : ' ';
    line += " " + cvar.name() + " " + quoted(cvar.string());
    if (!cvar.description().empty()) line += " - " + cvar.description();
    return line;
}

}  // namespace nq

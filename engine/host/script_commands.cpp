#include "host/script_commands.h"

#include "host/quoted.h"
#include "host/text_util.h"

namespace nq {
namespace {

void echo_command(CommandSystem& commands, const CommandArgs& args) {
    std::string text;
    for (size_t i = 1; i < args.argc(); ++i) {
        if (i > 1) text += ' ';
        text += args.argv(i);
    }
    commands.print(text + "\n");
}

void list_aliases(CommandSystem& commands) {
    std::vector<AliasInfo> aliases = commands.list_aliases();
    std::string text;
    for (const AliasInfo& alias : aliases) text += alias.name + " : " + alias.body + "\n";
    commands.print(text + count_noun(aliases.size(), "alias") + "\n");
}

// `alias` lists, `alias name` shows one, `alias name body...` defines (the body may be one
// quoted string or the raw rest of the line).
void alias_command(CommandSystem& commands, const CommandArgs& args) {
    if (args.argc() < 2) {
        list_aliases(commands);
        return;
    }
    const std::string& name = args.argv(1);
    if (args.argc() == 2) {
        const std::string* body = commands.find_alias(name);
        commands.print(body ? quoted(name) + " is " + quoted(*body) + "\n"
                            : "no alias named " + quoted(name) + "\n");
        return;
    }
    commands.set_alias(name, args.value_from(2));
}

void unalias_command(CommandSystem& commands, const CommandArgs& args) {
    if (args.argc() < 2) {
        commands.print("usage: unalias <name>\n");
        return;
    }
    if (!commands.remove_alias(args.argv(1))) {
        commands.print("unalias: no alias named " + quoted(args.argv(1)) + "\n");
    }
}

void exec_command(CommandSystem& commands, const CommandArgs& args) {
    if (args.argc() < 2) {
        commands.print("usage: exec <file>\n");
        return;
    }
    const std::string& path = args.argv(1);
    std::optional<std::string> text;
    if (is_safe_script_path(path)) text = commands.read_file(path);
    if (!text) {
        commands.print("couldn't exec " + path + "\n");
        return;
    }
    commands.print("execing " + path + "\n");
    commands.expand(*text, "exec " + path);
}

void cmdlist_command(CommandSystem& commands, const CommandArgs& args) {
    const std::string& prefix = args.argv(1);
    std::vector<CommandInfo> list = commands.list_commands(prefix);
    std::string text;
    for (const CommandInfo& command : list) {
        text += command.name;
        if (!command.description.empty()) text += " - " + command.description;
        text += "\n";
    }
    text += count_noun(list.size(), "command");
    if (!prefix.empty()) text += " beginning with " + quoted(prefix);
    commands.print(text + "\n");
}

}  // namespace

bool is_safe_script_path(std::string_view path) {
    if (path.empty() || path.front() == '/' || path.front() == '\\') return false;
    if (path.find(':') != std::string_view::npos) return false;  // C:\..., URLs
    size_t start = 0;
    while (start <= path.size()) {
        size_t end = path.find_first_of("/\\", start);
        if (end == std::string_view::npos) end = path.size();
        if (path.substr(start, end - start) == "..") return false;
        start = end + 1;
    }
    return true;
}

void register_script_commands(CommandSystem& commands) {
    commands.add_command(
        "echo", [&commands](const CommandArgs& a) { echo_command(commands, a); },
        "echo <text>: print the text to the console");
    commands.add_command(
        "alias", [&commands](const CommandArgs& a) { alias_command(commands, a); },
        "alias [name [commands]]: list, show or define an alias ($1..$9, $* take arguments)");
    commands.add_command(
        "unalias", [&commands](const CommandArgs& a) { unalias_command(commands, a); },
        "unalias <name>: remove an alias");
    commands.add_command(
        "exec", [&commands](const CommandArgs& a) { exec_command(commands, a); },
        "exec <file>: run the commands in a script file");
    commands.add_command(
        "wait", [&commands](const CommandArgs&) { commands.request_wait(); },
        "wait: run the rest of the commands next frame");
    commands.add_command(
        "cmdlist", [&commands](const CommandArgs& a) { cmdlist_command(commands, a); },
        "cmdlist [prefix]: list commands");
}

}  // namespace nq

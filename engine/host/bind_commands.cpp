#include "host/bind_commands.h"

#include "host/key_names.h"
#include "host/quoted.h"
#include "host/text_util.h"

namespace nq {
namespace {

void invalid_key(CommandSystem& commands, const std::string& key) {
    commands.print(quoted(key) + " isn't a valid key\n");
}

void show_binding(CommandSystem& commands, const KeyBindings& bindings, const std::string& key) {
    std::string name = quoted(*canonical_key_name(key));
    const std::string* command = bindings.binding(key);
    commands.print(command ? name + " = " + quoted(*command) + "\n" : name + " is not bound\n");
}

void bind_command(CommandSystem& commands, KeyBindings& bindings, const CommandArgs& args) {
    if (args.argc() < 2) {
        commands.print("usage: bind <key> [command]\n");
        return;
    }
    const std::string& key = args.argv(1);
    if (!canonical_key_name(key)) {
        invalid_key(commands, key);
    } else if (args.argc() == 2) {
        show_binding(commands, bindings, key);
    } else {
        bindings.bind(key, bound_command(args));
    }
}

void unbind_command(CommandSystem& commands, KeyBindings& bindings, const CommandArgs& args) {
    if (args.argc() < 2) {
        commands.print("usage: unbind <key>\n");
        return;
    }
    if (!bindings.unbind(args.argv(1))) invalid_key(commands, args.argv(1));
}

void bindlist_command(CommandSystem& commands, const KeyBindings& bindings) {
    std::string text;
    for (const auto& [key, command] : bindings.all()) {
        text += quoted(key) + " " + quoted(command) + "\n";
    }
    commands.print(text + count_noun(bindings.all().size(), "binding") + "\n");
}

}  // namespace

std::string bound_command(const CommandArgs& args) {
    return args.value_from(2);
}

void register_bind_commands(CommandSystem& commands, KeyBindings& bindings) {
    commands.add_command(
        "bind",
        [&commands, &bindings](const CommandArgs& a) { bind_command(commands, bindings, a); },
        "bind <key> [command]: show or set the command a key runs");
    commands.add_command(
        "unbind",
        [&commands, &bindings](const CommandArgs& a) { unbind_command(commands, bindings, a); },
        "unbind <key>: remove a key's binding");
    commands.add_command(
        "unbindall", [&bindings](const CommandArgs&) { bindings.unbind_all(); },
        "unbindall: remove every key binding");
    commands.add_command(
        "bindlist",
        [&commands, &bindings](const CommandArgs&) { bindlist_command(commands, bindings); },
        "bindlist: list key bindings");
}

}  // namespace nq

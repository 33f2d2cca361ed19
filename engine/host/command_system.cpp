#include "host/command_system.h"

#include "host/alias_expansion.h"
#include "host/cvar_commands.h"
#include "host/quoted.h"
#include "host/text_util.h"

namespace nq {

CommandSystem::CommandSystem(CvarRegistry& cvars, size_t buffer_bytes)
    : cvars_(cvars), buffer_(buffer_bytes) {}

void CommandSystem::print(std::string_view text) const {
    if (print_) print_(text);
}

std::optional<std::string> CommandSystem::read_file(const std::string& path) const {
    if (!read_file_) return std::nullopt;
    return read_file_(path);
}

bool CommandSystem::add_command(std::string_view name, CommandFn fn, std::string description,
                                OwnerId owner) {
    if (!is_valid_name(name) || !fn) return false;
    auto [it, inserted] = commands_.try_emplace(to_lower_ascii(name));
    if (!inserted) return false;
    it->second = Command{std::string(name), std::move(fn), std::move(description), owner};
    return true;
}

bool CommandSystem::remove_command(std::string_view name) {
    return commands_.erase(to_lower_ascii(name)) > 0;
}

size_t CommandSystem::remove_commands_of(OwnerId owner) {
    return std::erase_if(commands_, [&](const auto& entry) { return entry.second.owner == owner; });
}

bool CommandSystem::has_command(std::string_view name) const {
    return commands_.contains(to_lower_ascii(name));
}

std::vector<CommandInfo> CommandSystem::list_commands(std::string_view prefix) const {
    std::vector<CommandInfo> out;
    for (const auto& [key, command] : commands_) {
        if (istarts_with(key, prefix)) {
            out.push_back({command.name, command.description, command.owner});
        }
    }
    return out;
}

bool CommandSystem::set_alias(std::string_view name, std::string body) {
    const std::string quoted = nq::quoted(name);
    if (!is_valid_name(name)) {
        print("alias: invalid name " + quoted + "\n");
        return false;
    }
    if (has_command(name) || cvars_.find(name)) {
        print("alias: " + quoted + " is already a " + (has_command(name) ? "command" : "cvar") +
              "\n");
        return false;
    }
    aliases_[to_lower_ascii(name)] = AliasInfo{std::string(name), std::move(body)};
    return true;
}

bool CommandSystem::remove_alias(std::string_view name) {
    return aliases_.erase(to_lower_ascii(name)) > 0;
}

const std::string* CommandSystem::find_alias(std::string_view name) const {
    auto it = aliases_.find(to_lower_ascii(name));
    return it == aliases_.end() ? nullptr : &it->second.body;
}

std::vector<AliasInfo> CommandSystem::list_aliases() const {
    std::vector<AliasInfo> out;
    for (const auto& [key, alias] : aliases_) out.push_back(alias);
    return out;
}

void CommandSystem::add_text(std::string_view text) {
    if (!buffer_.add(text)) {
        print("command buffer overflow: dropped " + std::to_string(text.size()) + " bytes\n");
    }
}

void CommandSystem::insert_text(std::string_view text) {
    if (!buffer_.insert(text)) {
        print("command buffer overflow: dropped " + std::to_string(text.size()) + " bytes\n");
    }
}

void CommandSystem::execute() {
    if (executing_) return;
    struct Running {  // resets the frame state however the loop ends (a command may throw)
        CommandSystem& self;
        ~Running() {
            self.wait_requested_ = false;
            self.executing_ = false;
        }
    } running{*this};
    executing_ = true;
    wait_requested_ = false;
    expansions_this_frame_ = 0;
    while (!wait_requested_) {
        std::optional<CommandArgs> command = buffer_.next();
        if (!command) break;
        execute_command(*command);
    }
}

void CommandSystem::execute_command(const CommandArgs& args) {
    if (args.empty()) return;
    auto command = commands_.find(to_lower_ascii(args.name()));
    if (command != commands_.end()) {
        // A copy: the command may remove itself (a plugin's "unload" command) while running.
        CommandFn fn = command->second.fn;
        fn(args);
        return;
    }
    if (const std::string* body = find_alias(args.name())) {
        run_alias(*body, args);
        return;
    }
    if (Cvar* cvar = cvars_.find(args.name())) {
        show_or_set_cvar(*this, *cvar, args);
        return;
    }
    print("Unknown command \"" + args.name() + "\"\n");
}

void CommandSystem::run_alias(const std::string& body, const CommandArgs& args) {
    std::string what = "alias \"" + args.name() + "\"";
    std::optional<std::string> text = expand_alias(body, args, buffer_.max_bytes());
    if (!text) {
        print(what + ": expansion too long; ignored\n");
        return;
    }
    expand(*text, what);
}

bool CommandSystem::expand(std::string_view text, std::string_view what) {
    // Counted only inside execute(): outside it nothing runs, so nothing can loop.
    if (executing_ && ++expansions_this_frame_ > kMaxExpansionsPerFrame) {
        print(std::string(what) + ": more than " + std::to_string(kMaxExpansionsPerFrame) +
              " alias/exec expansions in one frame (recursive alias or exec?); "
              "command buffer cleared\n");
        buffer_.clear();
        return false;
    }
    if (!buffer_.insert(text)) {
        print(std::string(what) + ": command buffer overflow; ignored\n");
        return false;
    }
    return true;
}

std::string CommandSystem::take_pending_text() {
    std::string text(buffer_.pending());
    buffer_.clear();
    return text;
}

}  // namespace nq

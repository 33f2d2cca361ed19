#include "app/frame/plugin_commands.h"

#include <algorithm>

#include "host/text_util.h"

namespace nq {

namespace {

// Plugin commands are registered in the CommandSystem under this owner: the stacks here decide
// which plugin's function runs.
constexpr OwnerId kPluginCommandOwner = 0xfffffffeu;

}  // namespace

PluginCommands::~PluginCommands() {
    for (const auto& [key, stack] : stacks_) commands_.remove_command(key);
}

bool PluginCommands::add(OwnerId owner, const std::string& name, nqr_command_fn fn, void* user,
                         const std::string& description) {
    std::string key = to_lower_ascii(name);
    auto it = stacks_.find(key);
    if (it == stacks_.end()) {
        bool added = commands_.add_command(
            name, [this, key](const CommandArgs& args) { run(key, args); }, description,
            kPluginCommandOwner);
        if (!added) return false;
        it = stacks_.emplace(key, std::vector<Registration>{}).first;
    }
    it->second.push_back({owner, fn, user});
    return true;
}

void PluginCommands::release_owner(OwnerId owner) {
    for (auto it = stacks_.begin(); it != stacks_.end();) {
        std::erase_if(it->second, [owner](const Registration& r) { return r.owner == owner; });
        if (it->second.empty()) {
            commands_.remove_command(it->first);
            it = stacks_.erase(it);
        } else {
            ++it;
        }
    }
}

void PluginCommands::run(const std::string& key, const CommandArgs& args) {
    auto it = stacks_.find(key);
    if (it == stacks_.end() || it->second.empty()) return;
    // The C callback gets argv as C strings; built per call (console commands are not per frame).
    std::vector<std::string> words;
    for (size_t i = 0; i < args.argc(); ++i) words.emplace_back(args.argv(i));
    std::vector<const char*> argv;
    for (const auto& w : words) argv.push_back(w.c_str());
    const Registration& top = it->second.back();
    top.fn(top.user, static_cast<int>(argv.size()), argv.data());
}

}  // namespace nq

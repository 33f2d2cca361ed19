// Console commands registered by renderer plugins. During a swap the old and the new plugin
// both register the same names, so each name holds a stack of registrations: the newest runs,
// and unloading a plugin removes only its own entries (the command disappears with the last).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "host/command_system.h"
#include "nqr_renderer.h"

namespace nq {

class PluginCommands {
  public:
    explicit PluginCommands(CommandSystem& commands) : commands_(commands) {}
    ~PluginCommands();

    // False when the name is taken by an engine command or invalid.
    bool add(OwnerId owner, const std::string& name, nqr_command_fn fn, void* user,
             const std::string& description);
    void release_owner(OwnerId owner);

  private:
    struct Registration {
        OwnerId owner;
        nqr_command_fn fn;
        void* user;
    };
    void run(const std::string& key, const CommandArgs& args);

    CommandSystem& commands_;
    std::map<std::string, std::vector<Registration>> stacks_;  // key: lower-case name
};

}  // namespace nq

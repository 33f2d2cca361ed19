#include "host/host_core.h"

#include "host/bind_commands.h"
#include "host/cvar_commands.h"
#include "host/script_commands.h"

namespace nq {

HostCore::HostCore(size_t buffer_bytes) : commands_(cvars_, buffer_bytes) {
    register_script_commands(commands_);
    register_cvar_commands(commands_);
    register_bind_commands(commands_, bindings_);
}

void HostCore::queue_startup(const CommandLine& line) {
    startup_commands_ = line.command_text();
    if (commands_.read_file(kQuakeRcFile)) {
        // quake.rc decides the order; its `stuffcmds` runs the command line's +commands.
        commands_.add_command(
            "stuffcmds", [this](const CommandArgs&) { commands_.insert_text(startup_commands_); },
            "stuffcmds: run the command line's +commands (quake.rc does, once)");
        commands_.add_text(std::string("exec ") + kQuakeRcFile + "\n");
        return;
    }
    for (const char* file : {kConfigFile, kAutoexecFile}) {
        if (commands_.read_file(file)) commands_.add_text(std::string("exec ") + file + "\n");
    }
    commands_.add_text(startup_commands_);
}

void HostCore::release_owner(OwnerId owner) {
    commands_.remove_commands_of(owner);
    cvars_.release_owner(owner);
}

}  // namespace nq

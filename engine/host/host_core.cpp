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
    for (const char* file : {kConfigFile, kAutoexecFile}) {
        if (commands_.read_file(file)) commands_.add_text(std::string("exec ") + file + "\n");
    }
    commands_.add_text(line.command_text());
}

void HostCore::release_owner(OwnerId owner) {
    commands_.remove_commands_of(owner);
    cvars_.release_owner(owner);
}

}  // namespace nq

// The host core in one piece: cvars, commands with every built-in console command, and key
// bindings, wired together. What the engine (and a test) creates once.
//
//   HostCore host;
//   host.set_print(console_print);
//   host.set_file_reader(read_through_vfs);
//   host.queue_startup(CommandLine::from_main(argc, argv));
//   every frame: host.commands().execute();
//   on exit: save_config(path, host.cvars(), host.bindings());
#pragma once

#include "host/command_line.h"
#include "host/command_system.h"
#include "host/cvar_registry.h"
#include "host/key_bindings.h"
#include "host/owner.h"

namespace nq {

inline constexpr const char* kConfigFile = "config.cfg";
inline constexpr const char* kAutoexecFile = "autoexec.cfg";
inline constexpr const char* kQuakeRcFile = "quake.rc";

class HostCore {
  public:
    explicit HostCore(size_t buffer_bytes = kDefaultCommandBufferBytes);
    HostCore(const HostCore&) = delete;
    HostCore& operator=(const HostCore&) = delete;

    CvarRegistry& cvars() { return cvars_; }
    const CvarRegistry& cvars() const { return cvars_; }
    CommandSystem& commands() { return commands_; }
    const CommandSystem& commands() const { return commands_; }
    KeyBindings& bindings() { return bindings_; }
    const KeyBindings& bindings() const { return bindings_; }

    void set_print(PrintFn print) { commands_.set_print(std::move(print)); }
    void set_file_reader(FileReaderFn reader) { commands_.set_file_reader(std::move(reader)); }

    // Buffers the startup sequence. When the game has a quake.rc, Quake's: `exec quake.rc`,
    // whose `stuffcmds` runs the command line's +commands (LibreQuake's and id's run
    // default.cfg, config.cfg, autoexec.cfg, stuffcmds, startdemos). Without one: config.cfg,
    // then autoexec.cfg (each only if it exists), then the +commands. Run by execute().
    void queue_startup(const CommandLine& line);

    // A plugin is being unloaded: removes its commands and cvar callbacks; its cvars stay.
    void release_owner(OwnerId owner);

  private:
    CvarRegistry cvars_;
    CommandSystem commands_;  // after cvars_: it holds a reference to them
    KeyBindings bindings_;
    std::string startup_commands_;  // the command line's +commands, for stuffcmds
};

}  // namespace nq

// Commands, aliases and the command buffer: what runs the text typed in the console, read from
// config files, bound to keys or given on the command line (Quake's Cmd_* and Cbuf_*).
//
// Executing a command looks its first token up, case-insensitively, as a registered command,
// then an alias, then a cvar (no argument: print it; otherwise set it, as the user, to the
// argument -- or to the raw rest of the line when there are several); anything else prints
// `Unknown command "name"`. Not thread-safe.
#pragma once

#include <cstddef>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "host/command_args.h"
#include "host/command_buffer.h"
#include "host/cvar_registry.h"
#include "host/owner.h"

namespace nq {

using PrintFn = std::function<void(std::string_view text)>;
// Reads a script for `exec` (through the virtual filesystem or the user's directory);
// nullopt when the file does not exist or cannot be read.
using FileReaderFn = std::function<std::optional<std::string>(const std::string& path)>;
using CommandFn = std::function<void(const CommandArgs& args)>;

// Alias and exec expansions allowed during one execute() (one frame) before the buffer is
// declared runaway and cleared. Legitimate loops pace themselves with `wait`.
inline constexpr int kMaxExpansionsPerFrame = 1024;

struct CommandInfo {
    std::string name;
    std::string description;
    OwnerId owner;
};

struct AliasInfo {
    std::string name;
    std::string body;
};

class CommandSystem {
  public:
    explicit CommandSystem(CvarRegistry& cvars, size_t buffer_bytes = kDefaultCommandBufferBytes);
    CommandSystem(const CommandSystem&) = delete;
    CommandSystem& operator=(const CommandSystem&) = delete;

    CvarRegistry& cvars() { return cvars_; }
    const CvarRegistry& cvars() const { return cvars_; }

    // Output (the console). Every printed piece ends with a line break.
    void set_print(PrintFn print) { print_ = std::move(print); }
    void print(std::string_view text) const;
    void set_file_reader(FileReaderFn reader) { read_file_ = std::move(reader); }
    std::optional<std::string> read_file(const std::string& path) const;

    // False when the name is invalid or already a command (remove the old one first).
    bool add_command(std::string_view name, CommandFn fn, std::string description = {},
                     OwnerId owner = kEngineOwner);
    bool remove_command(std::string_view name);
    // A plugin is being unloaded: removes every command it registered; returns how many.
    size_t remove_commands_of(OwnerId owner);
    bool has_command(std::string_view name) const;
    // Sorted by lower-case name, filtered by a case-insensitive prefix.
    std::vector<CommandInfo> list_commands(std::string_view prefix = {}) const;

    // Aliases. set_alias refuses (with a printed reason) invalid names and names that are
    // commands or cvars, which the alias would hide or be hidden by.
    bool set_alias(std::string_view name, std::string body);
    bool remove_alias(std::string_view name);
    const std::string* find_alias(std::string_view name) const;
    std::vector<AliasInfo> list_aliases() const;

    // The buffer. Text that does not fit prints an overflow message and is dropped.
    void add_text(std::string_view text);
    void insert_text(std::string_view text);
    // Runs buffered commands until the buffer is empty or `wait` runs; call once per frame.
    // A call from inside a running command does nothing.
    void execute();
    // Ends the current execute() after the running command (the `wait` command).
    void request_wait() { wait_requested_ = true; }
    bool buffer_empty() const { return buffer_.empty(); }
    // Removes and returns everything still buffered (a demo holds the rest of a command line
    // such as "+timedemo demo +quit" until it ends, then inserts it back).
    std::string take_pending_text();
    const CommandBuffer& buffer() const { return buffer_; }

    // Runs one command now (not through the buffer).
    void execute_command(const CommandArgs& args);
    // Inserts alias or script text in front of the buffer, counting it against
    // kMaxExpansionsPerFrame; `what` names it in messages (`alias "x"`, `exec x.cfg`).
    bool expand(std::string_view text, std::string_view what);

  private:
    struct Command {
        std::string name;
        CommandFn fn;
        std::string description;
        OwnerId owner;
    };

    void run_alias(const std::string& body, const CommandArgs& args);

    CvarRegistry& cvars_;
    CommandBuffer buffer_;
    std::map<std::string, Command> commands_;   // key: lower-case name
    std::map<std::string, AliasInfo> aliases_;  // key: lower-case name
    PrintFn print_;
    FileReaderFn read_file_;
    bool wait_requested_ = false;
    bool executing_ = false;
    int expansions_this_frame_ = 0;
};

}  // namespace nq

// The program's command line, read with Quake's conventions:
//   -flag [value]   a flag, optionally followed by its value (any token that is neither a flag
//                   nor a +command: `-basedir ../shared/data`, `-width 1280`);
//   +command args   a console command with its arguments, up to the next +command or flag;
//                   each `+` starts a new command. A token like "-1" or "-.5" is a number,
//                   not a flag, so `+set volume -1` keeps its argument.
// Flags are matched case-insensitively, with their leading '-'. When a flag is repeated, the
// last one wins.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace nq {

class CommandLine {
  public:
    CommandLine() = default;
    // `args` without the program name.
    static CommandLine parse(const std::vector<std::string>& args);
    // main()'s argc/argv; argv[0] (the program) is skipped.
    static CommandLine from_main(int argc, const char* const* argv);

    bool has(std::string_view flag) const;
    // The value after the last occurrence of `flag`; nullopt when absent or given no value.
    std::optional<std::string> value(std::string_view flag) const;
    // Index (in order of appearance among flags) of the last occurrence, to tell which of two
    // conflicting flags came last; nullopt when absent.
    std::optional<size_t> last_position(std::string_view flag) const;

    // The +commands as command text, one per line: `+timedemo demo +quit` ->
    // "timedemo demo\nquit\n". Arguments are quoted where needed to stay one token.
    std::string command_text() const;
    // Tokens that belong to no flag or command (before the first flag or command).
    const std::vector<std::string>& stray() const { return stray_; }

  private:
    struct Flag {
        std::string name;
        std::optional<std::string> value;
    };
    const Flag* last(std::string_view flag) const;

    std::vector<Flag> flags_;
    std::vector<std::vector<std::string>> commands_;
    std::vector<std::string> stray_;
};

}  // namespace nq

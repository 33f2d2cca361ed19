// What every `mdltool` subcommand provides. To add one (e.g. `adjacency`, `export`): write
// <name>_command.{h,cpp} with a `run_<name>` function and add a row to kSubcommands in
// mdltool_main.cpp.
#pragma once

#include <string>
#include <vector>

namespace nq::mdltool {

// Exit statuses shared by all subcommands.
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailed = 1;  // some input could not be processed
inline constexpr int kExitUsage = 2;   // bad command line

struct Subcommand {
    const char* name;
    const char* synopsis;  // one line for `mdltool --help`
    // `args` are the arguments after the subcommand name. Returns an exit status.
    int (*run)(const std::vector<std::string>& args);
};

}  // namespace nq::mdltool

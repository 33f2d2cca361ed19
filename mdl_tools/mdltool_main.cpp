// mdltool: inspection and conversion of Quake alias models, one subcommand per job.
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include "adjacency_command.h"
#include "export_command.h"
#include "info_command.h"
#include "subcommand.h"

namespace {

using nq::mdltool::Subcommand;

constexpr Subcommand kSubcommands[] = {
    {"info", "info [--json] FILE|DIR...  header, skins, frames, bounds and warnings",
     nq::mdltool::run_info},
    {"adjacency", "adjacency [--json] [--time] FILE|DIR|PAK...  welds, splits, edges, verdict",
     nq::mdltool::run_adjacency},
    {"export", "export FILE [--frame N | --all-frames] [-o OUT.obj|.ply|.off]  mesh for Blender",
     nq::mdltool::run_export},
};

void print_usage(std::FILE* to) {
    std::fprintf(to, "usage: mdltool COMMAND [ARGS...]\ncommands:\n");
    for (const Subcommand& c : kSubcommands) std::fprintf(to, "  %s\n", c.synopsis);
    std::fprintf(to, "exit status: 0 ok, 1 some input failed, 2 usage error\n");
}

const Subcommand* find_subcommand(std::string_view name) {
    for (const Subcommand& c : kSubcommands) {
        if (name == c.name) return &c;
    }
    return nullptr;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        print_usage(stderr);
        return nq::mdltool::kExitUsage;
    }
    const std::string_view name = argv[1];
    if (name == "-h" || name == "--help" || name == "help") {
        print_usage(stdout);
        return nq::mdltool::kExitOk;
    }
    const Subcommand* command = find_subcommand(name);
    if (!command) {
        std::fprintf(stderr, "mdltool: unknown command '%s'\n", argv[1]);
        print_usage(stderr);
        return nq::mdltool::kExitUsage;
    }
    return command->run(std::vector<std::string>(argv + 2, argv + argc));
}

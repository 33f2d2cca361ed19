#include "info_command.h"

#include <cstdio>
#include <iostream>

#include "common/file_io.h"
#include "formats/mdl.h"
#include "info_report.h"
#include "model_paths.h"
#include "subcommand.h"

namespace nq::mdltool {

namespace {

constexpr const char* kUsage = "usage: mdltool info [--json] FILE|DIR...\n";

struct InfoOptions {
    bool json = false;
    std::vector<std::string> paths;
};

// Returns false (after printing why) on a usage error.
bool parse_options(const std::vector<std::string>& args, InfoOptions& options, bool& help) {
    for (const std::string& arg : args) {
        if (arg == "--json") {
            options.json = true;
        } else if (arg == "-h" || arg == "--help") {
            help = true;
        } else if (arg.size() > 1 && arg[0] == '-') {
            std::cerr << "mdltool info: unknown option '" << arg << "'\n" << kUsage;
            return false;
        } else {
            options.paths.push_back(arg);
        }
    }
    if (options.paths.empty() && !help) {
        std::cerr << "mdltool info: no model files or directories given\n" << kUsage;
        return false;
    }
    return true;
}

Result<Mdl> load_model(const std::string& path) {
    auto bytes = read_file(path);
    if (!bytes) return bytes.error();
    return parse_mdl(*bytes, path);
}

}  // namespace

int run_info(const std::vector<std::string>& args) {
    InfoOptions options;
    bool help = false;
    if (!parse_options(args, options, help)) return kExitUsage;
    if (help) {
        std::cout << kUsage;
        return kExitOk;
    }

    const PathExpansion expansion = expand_model_paths(options.paths, ".mdl");
    size_t failures = expansion.errors.size();
    for (const std::string& e : expansion.errors) std::cerr << "mdltool info: " << e << "\n";

    JsonWriter json;
    if (options.json) json.begin_object().key("models").begin_array();
    for (const std::string& path : expansion.files) {
        Result<Mdl> mdl = load_model(path);
        if (!mdl) {
            ++failures;
            std::cerr << "mdltool info: " << mdl.error().to_string() << "\n";
            if (options.json) write_error_json(json, path, mdl.error());
        } else if (options.json) {
            write_info_json(json, path, *mdl);
        } else {
            print_info_text(std::cout, path, *mdl);
        }
    }
    if (options.json) {
        json.end_array();
        json.key("path_errors").begin_array();
        for (const std::string& e : expansion.errors) json.value(e);
        json.end_array();
        json.field("failed", static_cast<uint64_t>(failures));
        json.end_object();
        std::cout << json.str();
    }
    return failures > 0 ? kExitFailed : kExitOk;
}

}  // namespace nq::mdltool

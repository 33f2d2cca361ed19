#include "adjacency_command.h"

#include <iostream>

#include "adjacency/alias_source.h"
#include "adjacency/model_adjacency.h"
#include "adjacency/paper_baseline.h"
#include "adjacency_inputs.h"
#include "adjacency_progress.h"
#include "adjacency_report.h"
#include "formats/mdl.h"
#include "render/alias_model.h"
#include "subcommand.h"

namespace nq::mdltool {

namespace {

constexpr const char* kUsage = "usage: mdltool adjacency [--json] [--time] FILE|DIR|PAK...\n";

struct AdjacencyOptions {
    bool json = false;
    bool timing = false;
    bool help = false;
    std::vector<std::string> paths;
};

// Returns false (after printing why) on a usage error.
bool parse_options(const std::vector<std::string>& args, AdjacencyOptions& options) {
    for (const std::string& arg : args) {
        if (arg == "--json") {
            options.json = true;
        } else if (arg == "--time") {
            options.timing = true;
        } else if (arg == "-h" || arg == "--help") {
            options.help = true;
        } else if (arg.size() > 1 && arg[0] == '-') {
            std::cerr << "mdltool adjacency: unknown option '" << arg << "'\n" << kUsage;
            return false;
        } else {
            options.paths.push_back(arg);
        }
    }
    if (options.paths.empty() && !options.help) {
        std::cerr << "mdltool adjacency: no model files, directories or paks given\n" << kUsage;
        return false;
    }
    return true;
}

Result<ModelReport> analyse(const ModelInput& input) {
    Result<std::vector<uint8_t>> bytes = input.read();
    if (!bytes) return bytes.error();
    Result<Mdl> mdl = parse_mdl(*bytes, input.name);
    if (!mdl) return mdl.error();
    const auto data = AliasModelData::build(std::move(*mdl));
    ModelReport report;
    report.name = input.name;
    const npr::adjacency::ModelAdjacency adjacency = npr::adjacency::recover_adjacency(data->abi());
    report.stats = adjacency.stats;
    report.verdict = adjacency.verdict;
    report.problems = adjacency.problems;
    report.paper = npr::adjacency::run_paper_baseline(npr::adjacency::AliasSource(data->abi()));
    return report;
}

void write_error_json(JsonWriter& json, const Error& error) {
    json.begin_object().field("path", error.file).field("ok", false);
    json.field("offset", error.offset).field("error", error.message).end_object();
}

}  // namespace

int run_adjacency(const std::vector<std::string>& args) {
    AdjacencyOptions options;
    if (!parse_options(args, options)) return kExitUsage;
    if (options.help) {
        std::cout << kUsage;
        print_legend(std::cout);
        return kExitOk;
    }
    const ModelInputs inputs = expand_model_inputs(options.paths);
    size_t failures = inputs.errors.size();
    for (const std::string& e : inputs.errors) std::cerr << "mdltool adjacency: " << e << "\n";

    JsonWriter json;
    AdjacencyTotals totals;
    if (options.json) {
        json.begin_object().key("models").begin_array();
    } else {
        print_table_header(std::cout, options.timing);
    }
    ProgressBar progress(inputs.models.size());
    for (size_t i = 0; i < inputs.models.size(); ++i) {
        progress.show(i, inputs.models[i].name);
        Result<ModelReport> report = analyse(inputs.models[i]);
        if (!report) {
            ++failures;
            progress.clear();
            std::cerr << "mdltool adjacency: " << report.error().to_string() << "\n";
            if (options.json) write_error_json(json, report.error());
            continue;
        }
        totals.add(*report);
        if (!report->problems.empty()) {
            ++failures;
            progress.clear();
            for (const std::string& p : report->problems) {
                std::cerr << "mdltool adjacency: " << report->name << ": check failed: " << p
                          << "\n";
            }
        }
        if (options.json) {
            write_model_json(json, *report);
        } else {
            print_table_row(std::cout, *report, options.timing);
        }
    }
    progress.clear();
    if (options.json) {
        json.end_array();
        write_totals_json(json, totals);
        json.key("path_errors").begin_array();
        for (const std::string& e : inputs.errors) json.value(e);
        json.end_array();
        json.field("failed", static_cast<uint64_t>(failures)).end_object();
        std::cout << json.str();
    } else {
        print_totals(std::cout, totals, options.timing);
    }
    return failures > 0 ? kExitFailed : kExitOk;
}

}  // namespace nq::mdltool

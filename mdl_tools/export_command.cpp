#include "export_command.h"

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>

#include "adjacency/model_adjacency.h"
#include "common/file_io.h"
#include "export_mesh.h"
#include "formats/mdl.h"
#include "render/alias_model.h"
#include "subcommand.h"

namespace nq::mdltool {

namespace {

constexpr const char* kUsage =
    "usage: mdltool export FILE [--frame N | --all-frames] [-o OUT.obj|.ply|.off]\n";

struct ExportOptions {
    std::string input;
    std::string output;  // default: the model's name with .obj, in the current directory
    std::optional<uint32_t> frame;
    bool all_frames = false;
    bool help = false;
};

std::optional<uint32_t> parse_index(const std::string& text) {
    if (text.empty() || text.size() > 9 ||
        text.find_first_not_of("0123456789") != std::string::npos) {
        return std::nullopt;
    }
    return static_cast<uint32_t>(std::stoul(text));
}

bool usage_error(const std::string& why) {
    std::cerr << "mdltool export: " << why << "\n" << kUsage;
    return false;
}

// Returns false (after printing why) on a usage error.
bool parse_options(const std::vector<std::string>& args, ExportOptions& o) {
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& arg = args[i];
        const bool has_value = i + 1 < args.size();
        if (arg == "-h" || arg == "--help") {
            o.help = true;
        } else if (arg == "--all-frames") {
            o.all_frames = true;
        } else if (arg == "--frame") {
            if (!has_value || !(o.frame = parse_index(args[++i]))) {
                return usage_error("--frame needs a frame number");
            }
        } else if (arg == "-o") {
            if (!has_value) return usage_error("-o needs a file name");
            o.output = args[++i];
        } else if (arg.size() > 1 && arg[0] == '-') {
            return usage_error("unknown option '" + arg + "'");
        } else if (o.input.empty()) {
            o.input = arg;
        } else {
            return usage_error("one model at a time ('" + arg + "' is extra)");
        }
    }
    if (o.help) return true;
    if (o.input.empty()) return usage_error("no model file given");
    if (o.frame && o.all_frames) return usage_error("--frame and --all-frames exclude each other");
    if (o.output.empty()) o.output = std::filesystem::path(o.input).stem().string() + ".obj";
    if (!is_supported_mesh_extension(o.output)) {
        return usage_error("'" + o.output + "': the output must end in .obj, .ply or .off");
    }
    return true;
}

// OUT.obj -> OUT_007.obj, with at least three digits and as many as the last frame needs.
std::string numbered_path(const std::string& path, uint32_t frame, uint32_t num_frames) {
    const std::filesystem::path p(path);
    const int digits = std::max<int>(3, int(std::to_string(num_frames - 1).size()));
    char number[16];
    std::snprintf(number, sizeof number, "_%0*u", digits, frame);
    return (p.parent_path() / (p.stem().string() + number + p.extension().string())).string();
}

Result<std::shared_ptr<const AliasModelData>> load_model(const std::string& path) {
    Result<std::vector<uint8_t>> bytes = read_file(path);
    if (!bytes) return bytes.error();
    Result<Mdl> mdl = parse_mdl(*bytes, path);
    if (!mdl) return mdl.error();
    return AliasModelData::build(std::move(*mdl));
}

// The pose a frame shows: its first (a frame group's first pose).
uint32_t first_pose(const nqr_alias_model& model, uint32_t frame) {
    return nqr_at(nqr_alias_frame, model.frames, frame)->first_pose;
}

}  // namespace

int run_export(const std::vector<std::string>& args) {
    ExportOptions options;
    if (!parse_options(args, options)) return kExitUsage;
    if (options.help) {
        std::cout << kUsage;
        return kExitOk;
    }
    const auto model = load_model(options.input);
    if (!model) {
        std::cerr << "mdltool export: " << model.error().to_string() << "\n";
        return kExitFailed;
    }
    const nqr_alias_model& abi = (*model)->abi();
    const uint32_t frame = options.frame.value_or(0);
    if (abi.num_frames == 0 || frame >= abi.num_frames) {
        std::cerr << "mdltool export: " << options.input << ": no frame " << frame
                  << " (the model has " << abi.num_frames << ")\n";
        return kExitFailed;
    }
    const npr::adjacency::ModelAdjacency adjacency = npr::adjacency::recover_adjacency(abi);
    std::cerr << npr::adjacency::verdict_log_line(options.input, adjacency.verdict) << "\n";
    const uint32_t first = options.all_frames ? 0 : frame;
    const uint32_t last = options.all_frames ? abi.num_frames : frame + 1;
    for (uint32_t f = first; f < last; ++f) {
        const std::string path =
            options.all_frames ? numbered_path(options.output, f, abi.num_frames) : options.output;
        const std::string error = write_mesh_pose(abi, adjacency, first_pose(abi, f), path);
        if (!error.empty()) {
            std::cerr << "mdltool export: " << error << "\n";
            return kExitFailed;
        }
        std::cout << path << "\n";
    }
    return kExitOk;
}

}  // namespace nq::mdltool

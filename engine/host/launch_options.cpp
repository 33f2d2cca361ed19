#include "host/launch_options.h"

#include <charconv>

namespace nq {
namespace {

// A flag that needs a value: complains when it is given without one.
std::optional<std::string> required_value(const CommandLine& line, const std::string& flag,
                                          const std::string& what,
                                          std::vector<std::string>& errors) {
    if (!line.has(flag)) return std::nullopt;
    std::optional<std::string> value = line.value(flag);
    if (!value || value->empty()) errors.push_back(flag + " needs " + what);
    return value;
}

// A whole number in 1..max, or nullopt (with an error when the flag was given).
std::optional<int> whole_number(const CommandLine& line, const std::string& flag,
                                const std::string& what, int max,
                                std::vector<std::string>& errors) {
    std::optional<std::string> text = required_value(line, flag, what, errors);
    if (!text || text->empty()) return std::nullopt;
    int value = 0;
    auto [end, ec] = std::from_chars(text->data(), text->data() + text->size(), value);
    if (ec != std::errc() || end != text->data() + text->size() || value < 1 || value > max) {
        errors.push_back(flag + ": expected a whole number from 1 to " + std::to_string(max) +
                         ", got \"" + *text + "\"");
        return std::nullopt;
    }
    return value;
}

std::optional<int> dimension(const CommandLine& line, const std::string& flag,
                             std::vector<std::string>& errors) {
    return whole_number(line, flag, "a size in pixels", kMaxWindowDimension, errors);
}

// -game names one directory under basedir, never a path (that could escape basedir).
bool is_plain_directory_name(const std::string& name) {
    return !name.empty() && name != "." && name != ".." &&
           name.find_first_of("/\\:") == std::string::npos;
}

std::optional<bool> fullscreen(const CommandLine& line) {
    std::optional<size_t> window = line.last_position("-window");
    std::optional<size_t> full = line.last_position("-fullscreen");
    if (!window && !full) return std::nullopt;
    if (window && full) return *full > *window;
    return full.has_value();
}

}  // namespace

LaunchOptions read_launch_options(const CommandLine& line) {
    LaunchOptions options;
    auto& errors = options.errors;
    options.basedir = required_value(line, "-basedir", "a directory", errors);
    options.game = required_value(line, "-game", "a game directory name", errors);
    if (options.game && !options.game->empty() && !is_plain_directory_name(*options.game)) {
        errors.push_back("-game: \"" + *options.game +
                         "\" must be a single directory name under the base directory, not a path");
        options.game.reset();
    }
    options.width = dimension(line, "-width", errors);
    options.height = dimension(line, "-height", errors);
    options.fullscreen = fullscreen(line);
    options.bench_json = required_value(line, "-benchjson", "a file name", errors);
    options.benchmark = required_value(line, "-benchmark", "a demo name", errors);
    options.benchmark_runs =
        whole_number(line, "-benchmarkruns", "a number of runs", kMaxBenchmarkRuns, errors)
            .value_or(1);
    options.bench_frames = required_value(line, "-benchframes", "a file name", errors);
    options.bench_trace = required_value(line, "-benchtrace", "a file name", errors);
    // A flag given without its value leaves no usable setting behind.
    for (auto* text : {&options.basedir, &options.game, &options.bench_json, &options.benchmark,
                       &options.bench_frames, &options.bench_trace}) {
        if (*text && (*text)->empty()) text->reset();
    }
    return options;
}

}  // namespace nq

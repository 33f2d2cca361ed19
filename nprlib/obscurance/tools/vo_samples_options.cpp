#include "vo_samples_options.h"

#include <charconv>
#include <functional>
#include <optional>
#include <string_view>

namespace nq::npr::obscurance::tools {

namespace {

// Parses the whole of text as a number of type T; nullopt on junk, trailing text or overflow.
template <class T>
std::optional<T> parse_number(std::string_view text) {
    T value{};
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
    return value;
}

using ValueHandler = std::function<std::string(VoSamplesOptions&, std::string_view)>;

struct OptionSpec {
    std::string_view name;  // without the leading "--"
    ValueHandler apply;     // returns an error message, or empty when the value was good
};

template <class T>
ValueHandler number_into(T GenerationParams::*field, const char* what) {
    return [field, what](VoSamplesOptions& o, std::string_view value) -> std::string {
        const std::optional<T> number = parse_number<T>(value);
        if (!number) return std::string("bad ") + what + " '" + std::string(value) + "'";
        o.params.*field = *number;
        return {};
    };
}

std::vector<OptionSpec> option_specs() {
    return {
        {"method",
         [](VoSamplesOptions& o, std::string_view value) -> std::string {
             if (parse_sample_method(value, o.method)) return {};
             return "unknown method '" + std::string(value) + "' (electrostatic, lloyd or poisson)";
         }},
        {"kind",
         [](VoSamplesOptions& o, std::string_view value) -> std::string {
             if (parse_sample_kind(value, o.kind)) return {};
             return "unknown kind '" + std::string(value) + "' (lines or points)";
         }},
        {"count",
         [](VoSamplesOptions& o, std::string_view value) -> std::string {
             o.count_given = true;
             return number_into(&GenerationParams::count, "count")(o, value);
         }},
        {"seed", number_into(&GenerationParams::seed, "seed")},
        {"restarts", number_into(&GenerationParams::restarts, "restart count")},
        {"resolution", number_into(&GenerationParams::resolution, "resolution")},
        {"format",
         [](VoSamplesOptions& o, std::string_view value) -> std::string {
             if (value == "text")
                 o.format = OutputFormat::text;
             else if (value == "cpp")
                 o.format = OutputFormat::cpp;
             else
                 return "unknown format '" + std::string(value) + "' (cpp or text)";
             return {};
         }},
        {"output",
         [](VoSamplesOptions& o, std::string_view value) -> std::string {
             if (value.empty()) return "empty output file name";
             o.output_path = value;
             return {};
         }},
    };
}

const OptionSpec* find_option(const std::vector<OptionSpec>& specs, std::string_view name) {
    for (const OptionSpec& spec : specs) {
        if (spec.name == name) return &spec;
    }
    return nullptr;
}

std::string set_output_argument(VoSamplesOptions& options, const std::string& argument) {
    if (!options.output_path.empty()) return "more than one output file ('" + argument + "')";
    options.output_path = argument;
    return {};
}

// Applies "--name[=value]" at arguments[index], taking the value from the next argument when
// there is no '='; advances index past what it used.
std::string apply_option(const std::vector<OptionSpec>& specs, VoSamplesOptions& options,
                         const std::vector<std::string>& arguments, size_t& index) {
    const std::string_view argument = arguments[index];
    const std::string_view body = argument.substr(2);
    const size_t equals = body.find('=');
    const std::string_view name = body.substr(0, equals);
    if (name == "help" && equals == std::string_view::npos) {
        options.help = true;
        return {};
    }
    const OptionSpec* spec = find_option(specs, name);
    if (!spec) return "unknown option '" + std::string(argument) + "'";
    if (equals != std::string_view::npos) return spec->apply(options, body.substr(equals + 1));
    if (index + 1 >= arguments.size()) return "option '--" + std::string(name) + "' needs a value";
    return spec->apply(options, arguments[++index]);
}

}  // namespace

ParsedOptions parse_vo_samples_options(const std::vector<std::string>& arguments) {
    const std::vector<OptionSpec> specs = option_specs();
    ParsedOptions parsed;
    bool options_ended = false;
    for (size_t index = 0; index < arguments.size() && parsed.error.empty(); ++index) {
        const std::string& argument = arguments[index];
        if (options_ended || argument == "-" || argument.rfind('-', 0) != 0) {
            parsed.error = set_output_argument(parsed.options, argument);
        } else if (argument == "--") {
            options_ended = true;
        } else if (argument == "-h") {
            parsed.options.help = true;
        } else if (argument.rfind("--", 0) == 0) {
            parsed.error = apply_option(specs, parsed.options, arguments, index);
        } else {
            parsed.error = "unknown option '" + argument + "'";
        }
    }
    VoSamplesOptions& options = parsed.options;
    if (!options.count_given) options.params.count = options.kind == SampleKind::lines ? 5 : 12;
    if (parsed.error.empty() && !options.help) parsed.error = validate(options.params);
    return parsed;
}

const char* vo_samples_usage() {
    return "usage: vo_samples [OPTIONS] [OUTPUT]\n"
           "Sample sets for volumetric obscurance (Loos & Sloan 2010): line samples on the unit\n"
           "disk or point samples in the unit ball, weighted by their Voronoi region's volume.\n"
           "  --method electrostatic|lloyd|poisson  generator (default electrostatic)\n"
           "  --kind lines|points   line samples (disk) or point samples (ball); default lines\n"
           "  --count N             samples (default 5 lines, 12 points)\n"
           "  --seed S              seed of the random starts (default 1)\n"
           "  --restarts R          random starts; the best set is kept (default 30)\n"
           "  --resolution R        Voronoi grid cells per axis (default 512 lines, 128 points)\n"
           "  --format cpp|text     C++ table for sample_tables.cpp, or text (default text)\n"
           "  --output FILE         write there instead of standard output (or give OUTPUT)\n"
           "  -h, --help            this help\n"
           "exit status: 0 ok, 1 output could not be written, 2 usage error\n";
}

std::string canonical_command(const VoSamplesOptions& options) {
    const GenerationParams& p = options.params;
    return std::string("vo_samples --method ") + sample_method_name(options.method) + " --kind " +
           sample_kind_name(options.kind) + " --count " + std::to_string(p.count) + " --seed " +
           std::to_string(p.seed) + " --restarts " + std::to_string(p.restarts) + " --resolution " +
           std::to_string(effective_resolution(p, options.kind)) + " --format " +
           (options.format == OutputFormat::cpp ? "cpp" : "text");
}

}  // namespace nq::npr::obscurance::tools

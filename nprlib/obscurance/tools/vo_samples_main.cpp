// vo_samples: generates sample sets for volumetric obscurance (nprlib/obscurance/sample_sets.h)
// and writes them as text or as the C++ tables nprlib/obscurance/sample_tables.cpp includes.
#include <cstdio>
#include <string>
#include <vector>

#include "obscurance/sample_sets.h"
#include "sample_set_writer.h"
#include "vo_samples_options.h"

namespace {

using namespace nq::npr::obscurance;
using namespace nq::npr::obscurance::tools;

constexpr int kExitOk = 0;
constexpr int kExitOutputFailed = 1;
constexpr int kExitUsage = 2;

template <class Set>
std::string render(const GenerationResult<Set>& result, const VoSamplesOptions& options) {
    const SampleSetHeader header{canonical_command(options), options.method,
                                 result.boundary_strength};
    return options.format == OutputFormat::cpp ? format_cpp(result.set, header)
                                               : format_text(result.set, header);
}

// The generated set as the chosen format, or an empty string and error set.
std::string generate(const VoSamplesOptions& options, std::string& error) {
    if (options.kind == SampleKind::lines) {
        const auto result = generate_line_samples(options.method, options.params);
        error = result.error;
        return result.ok() ? render(result, options) : std::string();
    }
    const auto result = generate_point_samples(options.method, options.params);
    error = result.error;
    return result.ok() ? render(result, options) : std::string();
}

// Writes text to file and closes it (flushes it, for standard output); false on any failure.
bool write_and_close(std::FILE* file, const std::string& text) {
    const bool written = std::fwrite(text.data(), 1, text.size(), file) == text.size();
    const bool closed = file == stdout ? std::fflush(file) == 0 : std::fclose(file) == 0;
    return written && closed;
}

}  // namespace

int main(int argc, char** argv) {
    const ParsedOptions parsed =
        parse_vo_samples_options(std::vector<std::string>(argv + 1, argv + argc));
    if (!parsed.error.empty()) {
        std::fprintf(stderr, "vo_samples: %s (see vo_samples --help)\n", parsed.error.c_str());
        return kExitUsage;
    }
    if (parsed.options.help) {
        std::fputs(vo_samples_usage(), stdout);
        return kExitOk;
    }
    // Opened before generating, which may take minutes, so that a bad path fails at once.
    const std::string& path = parsed.options.output_path;
    std::FILE* output = path.empty() ? stdout : std::fopen(path.c_str(), "w");
    if (!output) {
        std::fprintf(stderr, "vo_samples: cannot open '%s' for writing\n", path.c_str());
        return kExitOutputFailed;
    }
    std::string error;
    const std::string text = generate(parsed.options, error);
    if (!error.empty()) {
        if (output != stdout) std::fclose(output);
        std::fprintf(stderr, "vo_samples: %s\n", error.c_str());
        return kExitUsage;
    }
    if (!write_and_close(output, text)) {
        std::fprintf(stderr, "vo_samples: cannot write '%s'\n",
                     path.empty() ? "standard output" : path.c_str());
        return kExitOutputFailed;
    }
    return kExitOk;
}

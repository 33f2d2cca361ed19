// The vo_samples command line: GNU-style long options, in any order around the one optional
// argument (the output file, same as --output); "--option value" and "--option=value" both work,
// and "--" ends the options.
#pragma once

#include <string>
#include <vector>

#include "obscurance/sample_sets.h"

namespace nq::npr::obscurance::tools {

enum class OutputFormat { text, cpp };

struct VoSamplesOptions {
    SampleMethod method = SampleMethod::electrostatic;
    SampleKind kind = SampleKind::lines;
    GenerationParams params;
    bool count_given = false;  // without --count: 5 lines or 12 points
    OutputFormat format = OutputFormat::text;
    std::string output_path;  // empty: standard output
    bool help = false;
};

// The parsed options, or an error message naming the offending argument (error non-empty).
struct ParsedOptions {
    VoSamplesOptions options;
    std::string error;
};

ParsedOptions parse_vo_samples_options(const std::vector<std::string>& arguments);

const char* vo_samples_usage();

// The options written out in full, defaults included, as a command that regenerates the same
// set: "vo_samples --method electrostatic --kind lines --count 5 ...". Leaves out --output.
std::string canonical_command(const VoSamplesOptions& options);

}  // namespace nq::npr::obscurance::tools

// vo_samples' output: a sample set as text (one sample per line) or as a C++ table that
// nprlib/obscurance/sample_tables.cpp includes. Both start with the command that made them and
// the set's quality.
#pragma once

#include <string>

#include "obscurance/sample_sets.h"

namespace nq::npr::obscurance::tools {

struct SampleSetHeader {
    std::string command;  // canonical_command()
    SampleMethod method = SampleMethod::electrostatic;
    double boundary_strength = 0.0;  // electrostatic only
};

// "# ..." header lines, then "x y weight" (lines) or "x y z weight" (points) per sample.
std::string format_text(const LineSampleSet& set, const SampleSetHeader& header);
std::string format_text(const PointSampleSet& set, const SampleSetHeader& header);

// A comment header and "constexpr LineSampleRow kElectrostaticLines5[] = {...};" (PointSampleRow
// and "Points" for point sets), rows as sample_tables.h declares them.
std::string format_cpp(const LineSampleSet& set, const SampleSetHeader& header);
std::string format_cpp(const PointSampleSet& set, const SampleSetHeader& header);

// The table's name: "k" + method + kind + count, e.g. "kLloydPoints33".
std::string table_name(SampleMethod method, SampleKind kind, int count);

}  // namespace nq::npr::obscurance::tools

// The sample sets the volumetric obscurance renderer uses, generated once by vo_samples
// (nprlib/obscurance/tools; regenerate_tables.sh there rewrites tables/*.inc) at full
// resolution: line samples on the unit disk (5 and 9) and point samples in the unit ball
// (12 and 33) by the electrostatic method, and the same counts by Lloyd relaxation and plain
// Poisson-disk sampling for comparison; electrostatic sets of the neighbouring counts too (4, 6,
// 8, 10 lines; 11, 13, 32, 34 points), to check the paper's finding that its counts beat their
// neighbours. Weights sum to 1 within each set.
#pragma once

#include <span>

#include "obscurance/sample_sets.h"

namespace nq::npr::obscurance {

// Rows as a shader wants them: a point sample is one vec4 (position, weight).
struct LineSampleRow {
    float x, y, weight;
};
struct PointSampleRow {
    float x, y, z, weight;
};

// The counts with a table, for every method.
inline constexpr int kLineTableCounts[] = {5, 9};
inline constexpr int kPointTableCounts[] = {12, 33};
// The counts with an electrostatic table only.
inline constexpr int kNeighbourLineCounts[] = {4, 6, 8, 10};
inline constexpr int kNeighbourPointCounts[] = {11, 13, 32, 34};
inline constexpr int kMaxLineSamples = 10;
inline constexpr int kMaxPointSamples = 34;

// The committed set for method and count; an empty span when there is no table for them.
std::span<const LineSampleRow> line_sample_table(SampleMethod method, int count);
std::span<const PointSampleRow> point_sample_table(SampleMethod method, int count);

// A table as a sample set (positions and weights in double), for code that works on sets.
LineSampleSet to_sample_set(std::span<const LineSampleRow> rows);
PointSampleSet to_sample_set(std::span<const PointSampleRow> rows);

}  // namespace nq::npr::obscurance

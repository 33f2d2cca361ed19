// How evenly a sample set shares the domain: the spread of its Voronoi region measures
// (discrete_voronoi.h). Equal measures (both numbers at their ideal) mean every sample stands for
// the same share of the sphere, so each one's error counts alike.
#pragma once

#include <span>

namespace nq::npr::obscurance {

struct SampleQuality {
    double max_min_ratio = 0.0;    // largest measure / smallest; 1 is ideal, infinite if one is 0
    double relative_stddev = 0.0;  // standard deviation of the measures / their mean; 0 is ideal
};

// Empty measures give an infinite ratio: no set is worse.
SampleQuality measure_quality(std::span<const double> measures);

// Whether a is strictly better than b: the smaller max/min ratio, ties by the smaller spread.
bool is_better(const SampleQuality& a, const SampleQuality& b);

}  // namespace nq::npr::obscurance

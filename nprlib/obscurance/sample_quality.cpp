#include "obscurance/sample_quality.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace nq::npr::obscurance {

SampleQuality measure_quality(std::span<const double> measures) {
    constexpr double kInfinity = std::numeric_limits<double>::infinity();
    if (measures.empty()) return {kInfinity, kInfinity};
    const auto [smallest, largest] = std::minmax_element(measures.begin(), measures.end());
    double sum = 0.0;
    for (double m : measures) sum += m;
    const double mean = sum / measures.size();
    double squared_deviations = 0.0;
    for (double m : measures) squared_deviations += (m - mean) * (m - mean);
    SampleQuality quality;
    quality.max_min_ratio = *smallest > 0.0 ? *largest / *smallest : kInfinity;
    quality.relative_stddev =
        mean > 0.0 ? std::sqrt(squared_deviations / measures.size()) / mean : kInfinity;
    return quality;
}

bool is_better(const SampleQuality& a, const SampleQuality& b) {
    if (a.max_min_ratio != b.max_min_ratio) return a.max_min_ratio < b.max_min_ratio;
    return a.relative_stddev < b.relative_stddev;
}

}  // namespace nq::npr::obscurance

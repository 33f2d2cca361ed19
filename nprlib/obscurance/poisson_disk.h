// Plain random Poisson-disk sets by dart throwing: uniform random candidates, each kept when it
// is far enough from every point kept before. Deterministic given the generator's state.
#pragma once

#include <random>
#include <vector>

#include "obscurance/sample_domain.h"
#include "obscurance/sample_sets.h"

namespace nq::npr::obscurance {

// count positions in the unit disk (Dimension 2) or ball (3). The minimum distance starts near
// the even spacing and shrinks whenever darts keep missing, so that count points always fit.
template <int Dimension>
std::vector<Vec<Dimension>> poisson_disk_positions(int count, std::mt19937& rng);

// The best of params.restarts Poisson-disk sets (seeded with params.seed), weighted by their
// discrete Voronoi regions at the kind's resolution.
GenerationResult<LineSampleSet> poisson_disk_lines(const GenerationParams& params);
GenerationResult<PointSampleSet> poisson_disk_points(const GenerationParams& params);

}  // namespace nq::npr::obscurance

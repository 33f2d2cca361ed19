// Lloyd relaxation on the discrete Voronoi diagram (discrete_voronoi.h): every iteration moves
// each sample to its region's centroid (for line samples the centroid weighted by the sphere's
// depth). Converges toward a centroidal Voronoi tessellation, which spreads samples evenly but
// does not by itself equalise the region measures.
#pragma once

#include "obscurance/sample_sets.h"

namespace nq::npr::obscurance {

// params.restarts Poisson-disk starts (seeded with params.seed), each relaxed for
// params.lloyd_iterations iterations; the best state seen by quality is kept.
GenerationResult<LineSampleSet> lloyd_relax_lines(const GenerationParams& params);
GenerationResult<PointSampleSet> lloyd_relax_points(const GenerationParams& params);

}  // namespace nq::npr::obscurance

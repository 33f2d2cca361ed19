// The electrostatic method of Loos & Sloan (2010) for sample sets: the samples are charges that
// push each other apart with a 1/d^4 force, kept inside the disk / ball by a charge spread over
// its boundary (boundary_charge.h), and moved a small step along their net force at a time.
// After each round of steps every sample is pulled part of the way toward the (weighted) centroid
// of its discrete Voronoi region, and the state is measured (sample_quality.h). Every boundary
// strength in params.boundary_strengths is tried from each of params.restarts Poisson-disk
// starts; the best state seen is kept. Too weak a boundary lets samples pile onto the rim, too
// strong a one herds them to the centre; trying several strengths is the optimisation.
#pragma once

#include "obscurance/sample_sets.h"

namespace nq::npr::obscurance {

GenerationResult<LineSampleSet> electrostatic_lines(const GenerationParams& params);
GenerationResult<PointSampleSet> electrostatic_points(const GenerationParams& params);

}  // namespace nq::npr::obscurance

#include "obscurance/lloyd_relax.h"

#include <random>
#include <span>

#include "obscurance/best_sample_set.h"
#include "obscurance/discrete_voronoi.h"
#include "obscurance/poisson_disk.h"

namespace nq::npr::obscurance {

namespace {

// Offers every state of the relaxation, the start and the end included, to best.
template <int Dimension>
void relax(std::vector<Vec<Dimension>> positions, int iterations, int resolution,
           BestSampleSet<Dimension>& best) {
    for (int iteration = 0;; ++iteration) {
        VoronoiRegions<Dimension> regions = discrete_voronoi(std::span(positions), resolution);
        best.offer(positions, regions);
        if (iteration == iterations) return;
        positions = std::move(regions.centroids);
    }
}

template <int Dimension>
GenerationResult<SampleSet<Dimension>> best_lloyd(const GenerationParams& params, SampleKind kind) {
    using Result = GenerationResult<SampleSet<Dimension>>;
    if (std::string error = validate(params); !error.empty()) return Result::failure(error);
    const int resolution = effective_resolution(params, kind);
    std::mt19937 rng(params.seed);
    BestSampleSet<Dimension> best;
    for (int restart = 0; restart < params.restarts; ++restart) {
        relax(poisson_disk_positions<Dimension>(params.count, rng), params.lloyd_iterations,
              resolution, best);
    }
    return Result::success(best.set());
}

}  // namespace

GenerationResult<LineSampleSet> lloyd_relax_lines(const GenerationParams& params) {
    return best_lloyd<2>(params, SampleKind::lines);
}

GenerationResult<PointSampleSet> lloyd_relax_points(const GenerationParams& params) {
    return best_lloyd<3>(params, SampleKind::points);
}

}  // namespace nq::npr::obscurance

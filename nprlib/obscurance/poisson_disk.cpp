#include "obscurance/poisson_disk.h"

#include <span>

#include "obscurance/best_sample_set.h"
#include "obscurance/discrete_voronoi.h"
#include "obscurance/sample_domain.h"

namespace nq::npr::obscurance {

namespace {

// Starting distance as a fraction of the even spacing: random dart throwing jams well below
// the spacing of a perfect packing, so start a little under it.
constexpr double kFirstMinDistance = 0.8;
constexpr int kMissesBeforeShrinking = 1000;
constexpr double kShrinkFactor = 0.9;

template <int Dimension>
bool far_from_all(const std::vector<Vec<Dimension>>& kept, const Vec<Dimension>& candidate,
                  double min_distance) {
    for (const Vec<Dimension>& p : kept) {
        const Vec<Dimension> d = p - candidate;
        if (glm::dot(d, d) < min_distance * min_distance) return false;
    }
    return true;
}

}  // namespace

template <int Dimension>
std::vector<Vec<Dimension>> poisson_disk_positions(int count, std::mt19937& rng) {
    std::vector<Vec<Dimension>> kept;
    double min_distance = kFirstMinDistance * typical_spacing<Dimension>(count);
    int misses = 0;
    while (static_cast<int>(kept.size()) < count) {
        const Vec<Dimension> candidate = random_point_in_domain<Dimension>(rng);
        if (far_from_all(kept, candidate, min_distance)) {
            kept.push_back(candidate);
            misses = 0;
        } else if (++misses == kMissesBeforeShrinking) {
            min_distance *= kShrinkFactor;
            misses = 0;
        }
    }
    return kept;
}

template std::vector<glm::dvec2> poisson_disk_positions<2>(int count, std::mt19937& rng);
template std::vector<glm::dvec3> poisson_disk_positions<3>(int count, std::mt19937& rng);

namespace {

template <int Dimension>
GenerationResult<SampleSet<Dimension>> best_poisson_disk(const GenerationParams& params,
                                                         SampleKind kind) {
    using Result = GenerationResult<SampleSet<Dimension>>;
    if (std::string error = validate(params); !error.empty()) return Result::failure(error);
    const int resolution = effective_resolution(params, kind);
    std::mt19937 rng(params.seed);
    BestSampleSet<Dimension> best;
    for (int restart = 0; restart < params.restarts; ++restart) {
        const std::vector<Vec<Dimension>> positions =
            poisson_disk_positions<Dimension>(params.count, rng);
        best.offer(positions, discrete_voronoi(std::span(positions), resolution));
    }
    return Result::success(best.set());
}

}  // namespace

GenerationResult<LineSampleSet> poisson_disk_lines(const GenerationParams& params) {
    return best_poisson_disk<2>(params, SampleKind::lines);
}

GenerationResult<PointSampleSet> poisson_disk_points(const GenerationParams& params) {
    return best_poisson_disk<3>(params, SampleKind::points);
}

}  // namespace nq::npr::obscurance

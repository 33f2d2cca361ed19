// Sample sets for screen-space volumetric obscurance (Loos & Sloan, "Volumetric Obscurance",
// I3D 2010). Obscurance at a pixel is the fraction of a sphere around it that is occupied; it is
// estimated from a few samples, each standing for a share of the sphere's volume:
//   - line samples: points (x, y) on the unit disk, each integrating occupancy along the
//     sphere's depth z = +-sqrt(1 - x^2 - y^2) at that spot; its weight is the volume of its
//     Voronoi region on the disk, i.e. the integral of 2 sqrt(1 - x^2 - y^2) over the region;
//   - point samples: points in the unit ball; a weight is its Voronoi region's volume.
// Weights are normalised to sum to 1. A good set gives every sample nearly the same weight, so
// that each sample's error counts alike (quality: sample_quality.h).
// Generators (each keeps the best of several seeded random starts, deterministic given a seed):
//   poisson_disk.h   plain random Poisson-disk sets
//   lloyd_relax.h    Lloyd iterations on the discrete Voronoi diagram
//   electrostatic.h  the paper's method: 1/d^4 repulsion, a boundary charge, centroid pulls
// The Voronoi diagram is computed discretely (discrete_voronoi.h): the disk rasterised, the ball
// voxelised, each cell given to its nearest sample.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace nq::npr::obscurance {

// Positions and their weights, one weight per position. Dimension 2: line samples on the unit
// disk; dimension 3: point samples in the unit ball.
template <int Dimension>
struct SampleSet {
    std::vector<glm::vec<Dimension, double>> positions;
    std::vector<double> weights;
};
using LineSampleSet = SampleSet<2>;
using PointSampleSet = SampleSet<3>;

enum class SampleKind { lines, points };
enum class SampleMethod { electrostatic, lloyd, poisson };

// Names as the command line spells them ("lines", "electrostatic"); false for unknown names.
bool parse_sample_kind(std::string_view name, SampleKind& kind);
bool parse_sample_method(std::string_view name, SampleMethod& method);
const char* sample_kind_name(SampleKind kind);
const char* sample_method_name(SampleMethod method);

// Everything the generators take. Defaults are the ones the committed tables use.
struct GenerationParams {
    int count = 5;
    std::uint32_t seed = 1;
    int restarts = 30;  // random Poisson-disk starts; the best result by quality is kept
    // Cells per axis of the discrete Voronoi grid over [-1, 1]^D; 0 picks the kind's default.
    int resolution = 0;
    int lloyd_iterations = 30;
    // Electrostatic: rounds of repulsion steps, each followed by a pull toward the centroids.
    int electrostatic_rounds = 6;
    int repulsion_steps = 100;
    double centroid_pull = 0.5;  // fraction of the way to the centroid moved per round
    // Boundary charge strengths tried, in units of the strength that balances a point's
    // neighbour at the typical spacing (electrostatic.h); the best is kept.
    std::vector<double> boundary_strengths = {0.5, 1.0, 2.0, 4.0, 8.0, 16.0, 32.0};
};

constexpr int kDefaultLineResolution = 512;   // 512 x 512 disk raster
constexpr int kDefaultPointResolution = 128;  // 128^3 ball voxels

// The resolution a generator uses: params.resolution, or the kind's default when it is 0.
int effective_resolution(const GenerationParams& params, SampleKind kind);

// Empty when the parameters make sense, else what is wrong with them.
std::string validate(const GenerationParams& params);

// A generated set, or why there is none (error non-empty, set empty).
template <class Set>
struct GenerationResult {
    Set set;
    double boundary_strength = 0.0;  // electrostatic only: the strength the kept set used
    std::string error;
    bool ok() const { return error.empty(); }

    static GenerationResult success(Set set, double boundary_strength = 0.0) {
        GenerationResult result;
        result.set = std::move(set);
        result.boundary_strength = boundary_strength;
        return result;
    }
    static GenerationResult failure(std::string error) {
        GenerationResult result;
        result.error = std::move(error);
        return result;
    }
};

// The generator named by method, for lines (the unit disk) or points (the unit ball).
GenerationResult<LineSampleSet> generate_line_samples(SampleMethod method,
                                                      const GenerationParams& params);
GenerationResult<PointSampleSet> generate_point_samples(SampleMethod method,
                                                        const GenerationParams& params);

}  // namespace nq::npr::obscurance

#include "obscurance/electrostatic.h"

#include <cmath>
#include <random>
#include <span>

#include "obscurance/best_sample_set.h"
#include "obscurance/boundary_charge.h"
#include "obscurance/discrete_voronoi.h"
#include "obscurance/poisson_disk.h"

namespace nq::npr::obscurance {

namespace {

// Step lengths, as fractions of the even spacing, shrink geometrically from the first to the
// last step of a run, so that the samples first move freely and then settle.
constexpr double kFirstStep = 0.1;
constexpr double kLastStep = 0.001;
// The boundary force is infinite on the boundary; a step never lands a sample beyond this.
constexpr double kMaxRadius = 1.0 - 1e-3;
// Guards the pair force against coincident samples.
constexpr double kMinDistance2 = 1e-12;

double boundary_charge_force(double radius, glm::dvec2) {
    return circle_charge_force(radius);
}
double boundary_charge_force(double radius, glm::dvec3) {
    return sphere_charge_force(radius);
}

double balanced_density(int count, glm::dvec2) {
    return balanced_circle_density(count);
}
double balanced_density(int count, glm::dvec3) {
    return balanced_sphere_density(count);
}

template <int Dimension>
Vec<Dimension> boundary_push(const Vec<Dimension>& p, double density) {
    const double radius = glm::length(p);
    if (radius < 1e-12) return Vec<Dimension>(0.0);  // the centre: pushed equally every way
    return p * (density * boundary_charge_force(radius, Vec<Dimension>()) / radius);
}

template <int Dimension>
std::vector<Vec<Dimension>> net_forces(const std::vector<Vec<Dimension>>& positions,
                                       double density) {
    std::vector<Vec<Dimension>> forces;
    for (const Vec<Dimension>& p : positions) forces.push_back(boundary_push(p, density));
    for (size_t i = 0; i < positions.size(); ++i) {
        for (size_t j = i + 1; j < positions.size(); ++j) {
            const Vec<Dimension> d = positions[i] - positions[j];
            const double distance2 = std::max(glm::dot(d, d), kMinDistance2);
            // Magnitude 1 / distance^4 along d / distance.
            const Vec<Dimension> push = d / (distance2 * distance2 * std::sqrt(distance2));
            forces[i] += push;
            forces[j] -= push;
        }
    }
    return forces;
}

// Moves every sample step_length along its net force. Only the force's direction is used: 1/d^4
// forces span many orders of magnitude, and a fixed length keeps the steps stable.
template <int Dimension>
void repulsion_step(std::vector<Vec<Dimension>>& positions, double density, double step_length) {
    const std::vector<Vec<Dimension>> forces = net_forces(positions, density);
    for (size_t i = 0; i < positions.size(); ++i) {
        const double magnitude = glm::length(forces[i]);
        if (magnitude == 0.0) continue;
        positions[i] = clamp_into_domain<Dimension>(
            positions[i] + forces[i] * (step_length / magnitude), kMaxRadius);
    }
}

template <int Dimension>
void pull_toward_centroids(std::vector<Vec<Dimension>>& positions,
                           const std::vector<Vec<Dimension>>& centroids, double pull) {
    for (size_t i = 0; i < positions.size(); ++i) {
        positions[i] += (centroids[i] - positions[i]) * pull;
    }
}

// One run from a start at one boundary density; offers the state after every round, and the
// final one, to best. True when one of them became the best.
template <int Dimension>
bool run_electrostatic(std::vector<Vec<Dimension>> positions, double density,
                       const GenerationParams& params, int resolution,
                       BestSampleSet<Dimension>& best) {
    const double spacing = typical_spacing<Dimension>(params.count);
    const int total_steps = params.electrostatic_rounds * params.repulsion_steps;
    const double shrink_per_step =
        total_steps > 1 ? std::pow(kLastStep / kFirstStep, 1.0 / (total_steps - 1)) : 1.0;
    double step_length = kFirstStep * spacing;
    bool improved = false;
    for (int round = 0; round < params.electrostatic_rounds; ++round) {
        for (int step = 0; step < params.repulsion_steps; ++step) {
            repulsion_step(positions, density, step_length);
            step_length *= shrink_per_step;
        }
        const VoronoiRegions<Dimension> regions =
            discrete_voronoi(std::span(positions), resolution);
        improved |= best.offer(positions, regions);
        pull_toward_centroids(positions, regions.centroids, params.centroid_pull);
    }
    improved |= best.offer(positions, discrete_voronoi(std::span(positions), resolution));
    return improved;
}

template <int Dimension>
GenerationResult<SampleSet<Dimension>> best_electrostatic(const GenerationParams& params,
                                                          SampleKind kind) {
    using Result = GenerationResult<SampleSet<Dimension>>;
    if (std::string error = validate(params); !error.empty()) return Result::failure(error);
    const int resolution = effective_resolution(params, kind);
    const double unit_density = balanced_density(params.count, Vec<Dimension>());
    std::mt19937 rng(params.seed);
    BestSampleSet<Dimension> best;
    double best_strength = 0.0;
    for (int restart = 0; restart < params.restarts; ++restart) {
        const std::vector<Vec<Dimension>> start =
            poisson_disk_positions<Dimension>(params.count, rng);
        for (double strength : params.boundary_strengths) {
            if (run_electrostatic(start, strength * unit_density, params, resolution, best)) {
                best_strength = strength;
            }
        }
    }
    return Result::success(best.set(), best_strength);
}

}  // namespace

GenerationResult<LineSampleSet> electrostatic_lines(const GenerationParams& params) {
    return best_electrostatic<2>(params, SampleKind::lines);
}

GenerationResult<PointSampleSet> electrostatic_points(const GenerationParams& params) {
    return best_electrostatic<3>(params, SampleKind::points);
}

}  // namespace nq::npr::obscurance

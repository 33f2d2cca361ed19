// Small helpers the generators share, written once for the disk (dimension 2, line samples) and
// the ball (dimension 3, point samples): the domain's measure and typical sample spacing, random
// points in it, keeping points inside it.
#pragma once

#include <cmath>
#include <numbers>
#include <random>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace nq::npr::obscurance {

template <int Dimension>
using Vec = glm::vec<Dimension, double>;

// Area of the unit disk, volume of the unit ball.
template <int Dimension>
constexpr double domain_measure() {
    return Dimension == 2 ? std::numbers::pi : 4.0 / 3.0 * std::numbers::pi;
}

// The side of a cell when the domain is shared evenly by count samples.
template <int Dimension>
double typical_spacing(int count) {
    return std::pow(domain_measure<Dimension>() / count, 1.0 / Dimension);
}

// Uniform in [0, 1) from the generator's raw 32-bit output: std::uniform_real_distribution is
// implementation-defined, and the committed tables must regenerate identically everywhere.
inline double unit_uniform(std::mt19937& rng) {
    return rng() * (1.0 / 4294967296.0);
}

// Uniform in the unit disk / ball, by rejection from the enclosing square / cube.
template <int Dimension>
Vec<Dimension> random_point_in_domain(std::mt19937& rng) {
    for (;;) {
        Vec<Dimension> p;
        for (int axis = 0; axis < Dimension; ++axis) p[axis] = 2.0 * unit_uniform(rng) - 1.0;
        if (glm::dot(p, p) < 1.0) return p;
    }
}

// Moves p radially back to max_radius when it has strayed beyond it.
template <int Dimension>
Vec<Dimension> clamp_into_domain(Vec<Dimension> p, double max_radius) {
    const double radius = glm::length(p);
    return radius > max_radius ? p * (max_radius / radius) : p;
}

}  // namespace nq::npr::obscurance

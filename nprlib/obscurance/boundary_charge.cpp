#include "obscurance/boundary_charge.h"

#include <cmath>
#include <numbers>

#include "obscurance/sample_domain.h"

namespace nq::npr::obscurance {

namespace {

// Quadrature nodes for the circle. The integrand peaks sharply at the nearest boundary point
// when the sample is close to the boundary; the substitution angle = pi s^3 crowds nodes there.
constexpr int kCircleNodes = 512;

// x-component of the 1/d^4 push of the circle point at angle phi on the sample at (radius, 0).
double circle_element_push(double radius, double phi) {
    const double cos_phi = std::cos(phi);
    const double distance2 = 1.0 + radius * radius - 2.0 * radius * cos_phi;
    return (radius - cos_phi) / (distance2 * distance2 * std::sqrt(distance2));
}

}  // namespace

double circle_charge_force(double radius) {
    // Symmetric in phi: twice the integral over [0, pi], midpoint rule in s, phi = pi s^3.
    double sum = 0.0;
    for (int node = 0; node < kCircleNodes; ++node) {
        const double s = (node + 0.5) / kCircleNodes;
        const double phi = std::numbers::pi * s * s * s;
        const double dphi_ds = 3.0 * std::numbers::pi * s * s;
        sum += circle_element_push(radius, phi) * dphi_ds;
    }
    return 2.0 * sum / kCircleNodes;
}

double sphere_charge_force(double radius) {
    // Rings of the sphere at height u = cos(theta) push along the axis through the sample with
    // (r - u) / (1 + r^2 - 2 r u)^(5/2); their integral over u in [-1, 1] times the ring
    // circumference 2 pi has the closed form below (p = 1 - r, q = 1 + r).
    const double r = radius;
    if (r < 1e-4) return 2.0 * std::numbers::pi * (-4.0 / 3.0) * r;  // the series at the centre
    const double p = 1.0 - r;
    const double q = 1.0 + r;
    const double integral =
        ((2.0 / 3.0) * (p / (q * q) - q / (p * p)) + 2.0 * (1.0 / p - 1.0 / q)) / (4.0 * r * r);
    return 2.0 * std::numbers::pi * integral;
}

double balanced_circle_density(int count) {
    // Line at depth s/2 pushes with density * 4 / (3 (s/2)^3); a neighbour at s with 1 / s^4.
    const double spacing = typical_spacing<2>(count);
    return 3.0 / (32.0 * spacing);
}

double balanced_sphere_density(int count) {
    // Plane at depth s/2 pushes with density * 2 pi / (3 (s/2)^2); a neighbour at s with 1 / s^4.
    const double spacing = typical_spacing<3>(count);
    return 3.0 / (8.0 * std::numbers::pi * spacing * spacing);
}

}  // namespace nq::npr::obscurance

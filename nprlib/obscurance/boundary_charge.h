// The boundary charge of the electrostatic method (electrostatic.h): a charge spread evenly over
// the unit circle (line samples) or the unit sphere (point samples), repelling the samples with
// the same 1/d^4 law they repel each other with. Inside, the net force points to the centre and
// grows without bound toward the boundary, which keeps samples in; its strength decides how close
// to the boundary they settle.
#pragma once

namespace nq::npr::obscurance {

// Radial force at distance radius (0 <= radius < 1) from the centre, per unit charge density
// (charge per unit length of the circle / area of the sphere); negative means inward.
// Near the boundary, at depth d = 1 - radius, they approach a straight line's -4 / (3 d^3) and a
// plane's -2 pi / (3 d^2).
double circle_charge_force(double radius);
double sphere_charge_force(double radius);

// The charge density at which the boundary's push on a sample half a spacing from it matches the
// push of a neighbour one spacing away, for count samples sharing the disk / ball evenly: the
// unit the strengths in GenerationParams::boundary_strengths are given in.
double balanced_circle_density(int count);
double balanced_sphere_density(int count);

}  // namespace nq::npr::obscurance

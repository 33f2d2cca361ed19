// Voronoi regions of sample positions, computed discretely: [-1, 1]^D is cut into resolution^D
// cells, cells whose centre lies outside the unit disk / ball are dropped, and every other cell
// goes to its nearest sample. Line samples weigh each disk cell by the sphere's depth there,
// 2 sqrt(1 - x^2 - y^2), so a region's measure is the volume of the sphere it stands for; point
// samples weigh every ball cell alike (volume).
#pragma once

#include <span>
#include <vector>

#include "obscurance/sample_domain.h"

namespace nq::npr::obscurance {

template <int Dimension>
struct VoronoiRegions {
    // Each sample's region measure as a fraction of the whole domain's (they sum to 1).
    std::vector<double> measures;
    // Each region's weighted centroid; a sample whose region caught no cell keeps its position.
    std::vector<Vec<Dimension>> centroids;
};

VoronoiRegions<2> discrete_voronoi_lines(std::span<const glm::dvec2> positions, int resolution);
VoronoiRegions<3> discrete_voronoi_points(std::span<const glm::dvec3> positions, int resolution);

// The same two, chosen by the positions' dimension (for code written once for both).
inline VoronoiRegions<2> discrete_voronoi(std::span<const glm::dvec2> positions, int resolution) {
    return discrete_voronoi_lines(positions, resolution);
}
inline VoronoiRegions<3> discrete_voronoi(std::span<const glm::dvec3> positions, int resolution) {
    return discrete_voronoi_points(positions, resolution);
}

}  // namespace nq::npr::obscurance

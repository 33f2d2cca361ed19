#include "obscurance/discrete_voronoi.h"

#include <cmath>
#include <cstddef>
#include <limits>

namespace nq::npr::obscurance {

namespace {

template <int Dimension>
size_t nearest_index(std::span<const Vec<Dimension>> positions, const Vec<Dimension>& p) {
    size_t nearest = 0;
    double nearest_distance2 = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < positions.size(); ++i) {
        const Vec<Dimension> d = positions[i] - p;
        const double distance2 = glm::dot(d, d);
        if (distance2 < nearest_distance2) {
            nearest_distance2 = distance2;
            nearest = i;
        }
    }
    return nearest;
}

// Sums of cell weights and weighted cell centres per region, turned into measures and centroids
// once every cell is in.
template <int Dimension>
class RegionAccumulator {
  public:
    explicit RegionAccumulator(std::span<const Vec<Dimension>> positions)
        : positions_(positions),
          weight_sums_(positions.size(), 0.0),
          weighted_centres_(positions.size(), Vec<Dimension>(0.0)) {}

    void add_cell(const Vec<Dimension>& centre, double weight) {
        const size_t region = nearest_index<Dimension>(positions_, centre);
        weight_sums_[region] += weight;
        weighted_centres_[region] += weight * centre;
        total_weight_ += weight;
    }

    VoronoiRegions<Dimension> finish() const {
        VoronoiRegions<Dimension> regions;
        for (size_t i = 0; i < positions_.size(); ++i) {
            const double sum = weight_sums_[i];
            regions.measures.push_back(total_weight_ > 0.0 ? sum / total_weight_ : 0.0);
            regions.centroids.push_back(sum > 0.0 ? weighted_centres_[i] / sum : positions_[i]);
        }
        return regions;
    }

  private:
    std::span<const Vec<Dimension>> positions_;
    std::vector<double> weight_sums_;
    std::vector<Vec<Dimension>> weighted_centres_;
    double total_weight_ = 0.0;
};

// Centre of cell `index` along an axis cut into `resolution` cells over [-1, 1].
double cell_centre(int index, int resolution) {
    return -1.0 + (index + 0.5) * 2.0 / resolution;
}

}  // namespace

VoronoiRegions<2> discrete_voronoi_lines(std::span<const glm::dvec2> positions, int resolution) {
    RegionAccumulator<2> regions(positions);
    if (positions.empty()) return regions.finish();
    for (int row = 0; row < resolution; ++row) {
        const double y = cell_centre(row, resolution);
        for (int column = 0; column < resolution; ++column) {
            const double x = cell_centre(column, resolution);
            const double depth2 = 1.0 - x * x - y * y;
            if (depth2 <= 0.0) continue;
            // The sphere's depth extent at (x, y): the length the line sample integrates over.
            regions.add_cell({x, y}, 2.0 * std::sqrt(depth2));
        }
    }
    return regions.finish();
}

VoronoiRegions<3> discrete_voronoi_points(std::span<const glm::dvec3> positions, int resolution) {
    RegionAccumulator<3> regions(positions);
    if (positions.empty()) return regions.finish();
    for (int slice = 0; slice < resolution; ++slice) {
        const double z = cell_centre(slice, resolution);
        for (int row = 0; row < resolution; ++row) {
            const double y = cell_centre(row, resolution);
            for (int column = 0; column < resolution; ++column) {
                const double x = cell_centre(column, resolution);
                if (x * x + y * y + z * z >= 1.0) continue;
                regions.add_cell({x, y, z}, 1.0);
            }
        }
    }
    return regions.finish();
}

}  // namespace nq::npr::obscurance

// A uniform grid over a fixed set of points, for finding the points near a position without
// allocating: cells of `cell_size` over the points' bounding box, each holding the indices of
// its points (one shared index array, cell ranges by offset).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace nq {

inline constexpr size_t kMaxGridCells = size_t{1} << 21;

class PointGrid {
  public:
    PointGrid() = default;
    // The cell grows beyond `cell_size` when the box would need more than kMaxGridCells cells.
    PointGrid(std::span<const glm::vec3> points, float cell_size);

    float cell_size() const { return cell_; }
    bool empty() const { return indices_.empty(); }

    // Calls visit(index) for each point of the cells at Chebyshev distance `ring` (in cells)
    // from the cell holding `p` (a position outside the grid counts from the nearest cell).
    // Rings 0 and 1 hold every point within cell_size() of p.
    template <class Visit>
    void for_each_in_ring(const glm::vec3& p, int ring, Visit&& visit) const;

  private:
    std::array<int, 3> cell_of(const glm::vec3& p) const;
    size_t cell_index(int x, int y, int z) const {
        return (size_t(z) * size_t(dims_[1]) + size_t(y)) * size_t(dims_[0]) + size_t(x);
    }

    glm::vec3 origin_{0.0f};
    float cell_ = 1.0f;
    std::array<int, 3> dims_{0, 0, 0};
    std::vector<uint32_t> starts_;   // per cell, then one past the last
    std::vector<uint32_t> indices_;  // point indices, cell by cell
};

template <class Visit>
void PointGrid::for_each_in_ring(const glm::vec3& p, int ring, Visit&& visit) const {
    if (indices_.empty() || ring < 0) return;
    const std::array<int, 3> c = cell_of(p);
    const int z0 = std::max(c[2] - ring, 0), z1 = std::min(c[2] + ring, dims_[2] - 1);
    const int y0 = std::max(c[1] - ring, 0), y1 = std::min(c[1] + ring, dims_[1] - 1);
    const int x0 = std::max(c[0] - ring, 0), x1 = std::min(c[0] + ring, dims_[0] - 1);
    for (int z = z0; z <= z1; ++z) {
        for (int y = y0; y <= y1; ++y) {
            for (int x = x0; x <= x1; ++x) {
                const int away =
                    std::max({std::abs(x - c[0]), std::abs(y - c[1]), std::abs(z - c[2])});
                if (away != ring) continue;
                const size_t cell = cell_index(x, y, z);
                for (uint32_t k = starts_[cell]; k < starts_[cell + 1]; ++k) visit(indices_[k]);
            }
        }
    }
}

}  // namespace nq

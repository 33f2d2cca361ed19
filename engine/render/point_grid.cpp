#include "render/point_grid.h"

namespace nq {

namespace {

constexpr int kMaxCellsPerAxis = 1 << 20;

int cells_for(float extent, float cell) {
    const float n = std::floor(extent / cell) + 1.0f;
    return int(std::clamp(n, 1.0f, float(kMaxCellsPerAxis)));
}

}  // namespace

PointGrid::PointGrid(std::span<const glm::vec3> points, float cell_size) {
    if (points.empty()) return;
    glm::vec3 lo(points[0]), hi(points[0]);
    for (const glm::vec3& p : points) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    origin_ = lo;
    cell_ = cell_size > 0.0f && std::isfinite(cell_size) ? cell_size : 1.0f;
    const glm::vec3 extent = hi - lo;
    for (;;) {
        dims_ = {cells_for(extent.x, cell_), cells_for(extent.y, cell_),
                 cells_for(extent.z, cell_)};
        const double cells = double(dims_[0]) * double(dims_[1]) * double(dims_[2]);
        if (cells <= double(kMaxGridCells)) break;
        cell_ *= 2.0f;
    }
    const size_t cells = size_t(dims_[0]) * size_t(dims_[1]) * size_t(dims_[2]);
    std::vector<uint32_t> cell_of_point(points.size());
    starts_.assign(cells + 1, 0);
    for (size_t i = 0; i < points.size(); ++i) {
        const std::array<int, 3> c = cell_of(points[i]);
        cell_of_point[i] = uint32_t(cell_index(c[0], c[1], c[2]));
        ++starts_[cell_of_point[i] + 1];
    }
    for (size_t c = 0; c < cells; ++c) starts_[c + 1] += starts_[c];
    indices_.resize(points.size());
    std::vector<uint32_t> fill(starts_.begin(), starts_.end() - 1);
    for (size_t i = 0; i < points.size(); ++i) indices_[fill[cell_of_point[i]]++] = uint32_t(i);
}

std::array<int, 3> PointGrid::cell_of(const glm::vec3& p) const {
    std::array<int, 3> c{};
    for (int a = 0; a < 3; ++a) {
        const float f = std::floor((p[a] - origin_[a]) / cell_);
        c[a] = std::isfinite(f) ? int(std::clamp(f, 0.0f, float(dims_[a] - 1))) : 0;
    }
    return c;
}

}  // namespace nq

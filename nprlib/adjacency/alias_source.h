// Read-only access to an alias model as the renderer ABI hands it over (nqr_alias_model):
// triangles in file order, packed vertices of every pose, decoded model-space positions.
// Null arrays with non-zero counts are read as empty, so a broken view cannot be walked past
// its end; indices are checked by the callers that use them (triangle_filter).
#pragma once

#include <array>
#include <cstdint>

#include <glm/vec3.hpp>

#include "nqr_renderer.h"

namespace nq::npr::adjacency {

using PackedPosition = std::array<uint8_t, 3>;

struct AliasTriangle {
    int32_t faces_front = 0;
    std::array<int32_t, 3> vertices{};  // as stored: clockwise seen from outside (Quake)
};

class AliasSource {
  public:
    explicit AliasSource(const nqr_alias_model& model);

    uint32_t num_vertices() const { return num_vertices_; }
    uint32_t num_triangles() const { return num_triangles_; }
    uint32_t num_poses() const { return num_poses_; }

    AliasTriangle triangle(uint32_t index) const;
    bool vertex_in_range(int32_t index) const {
        return index >= 0 && static_cast<uint32_t>(index) < num_vertices_;
    }
    PackedPosition packed(uint32_t pose, uint32_t vertex) const;
    // Model space: scale * packed + origin.
    glm::vec3 position(uint32_t pose, uint32_t vertex) const;
    const glm::vec3& scale() const { return scale_; }

  private:
    const nqr_alias_model& model_;
    uint32_t num_vertices_ = 0, num_triangles_ = 0, num_poses_ = 0;
    glm::vec3 scale_{0.0f}, origin_{0.0f};
};

}  // namespace nq::npr::adjacency

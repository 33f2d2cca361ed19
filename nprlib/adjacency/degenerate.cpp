#include "adjacency/degenerate.h"

namespace nq::npr::adjacency {

namespace {

bool zero_area_in_pose(const AliasSource& source, uint32_t pose,
                       const std::array<uint32_t, 3>& vertices) {
    const PackedPosition a = source.packed(pose, vertices[0]);
    const PackedPosition b = source.packed(pose, vertices[1]);
    const PackedPosition c = source.packed(pose, vertices[2]);
    int32_t u[3], w[3];
    for (int i = 0; i < 3; ++i) {
        u[i] = int32_t(b[i]) - int32_t(a[i]);
        w[i] = int32_t(c[i]) - int32_t(a[i]);
    }
    // Model-space cross component i is (packed cross i) * scale[j] * scale[k], j, k != i.
    const glm::vec3& s = source.scale();
    const int32_t cross[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2],
                              u[0] * w[1] - u[1] * w[0]};
    for (int i = 0; i < 3; ++i) {
        if (cross[i] != 0 && s[(i + 1) % 3] != 0.0f && s[(i + 2) % 3] != 0.0f) return false;
    }
    return true;
}

}  // namespace

bool zero_area_in_every_pose(const AliasSource& source, const std::array<uint32_t, 3>& vertices) {
    if (source.num_poses() == 0) return false;
    for (uint32_t pose = 0; pose < source.num_poses(); ++pose) {
        if (!zero_area_in_pose(source, pose, vertices)) return false;
    }
    return true;
}

}  // namespace nq::npr::adjacency

#include "common/vec3_math.h"

#include <numbers>

namespace nq {

Basis angle_vectors(const Vec3& angles) {
    constexpr float kToRadians = std::numbers::pi_v<float> / 180.0f;
    const float sp = std::sin(angles[0] * kToRadians), cp = std::cos(angles[0] * kToRadians);
    const float sy = std::sin(angles[1] * kToRadians), cy = std::cos(angles[1] * kToRadians);
    const float sr = std::sin(angles[2] * kToRadians), cr = std::cos(angles[2] * kToRadians);
    Basis b;
    b.forward = {cp * cy, cp * sy, -sp};
    b.right = {-sr * sp * cy + cr * sy, -sr * sp * sy - cr * cy, -sr * cp};
    b.up = {cr * sp * cy + sr * sy, cr * sp * sy - sr * cy, cr * cp};
    return b;
}

}  // namespace nq

#include "client/client_math.h"

#include <numbers>

namespace nq {

float normalize(Vec3& v) {
    float length = vlength(v);
    if (length > 0) v = vscale(v, 1.0f / length);
    return length;
}

float angle_delta(float from, float to) {
    float d = std::fmod(to - from, 360.0f);
    if (d >= 180.0f) d -= 360.0f;
    if (d < -180.0f) d += 360.0f;
    return d;
}

float lerp_angle(float from, float to, float frac) {
    return from + frac * angle_delta(from, to);
}

float angle_mod(float degrees) {
    float a = std::fmod(degrees, 360.0f);
    return a < 0 ? a + 360.0f : a;
}

Basis angle_vectors(const Vec3& angles) {
    constexpr float kToRadians = std::numbers::pi_v<float> / 180.0f;
    float sp = std::sin(angles[0] * kToRadians), cp = std::cos(angles[0] * kToRadians);
    float sy = std::sin(angles[1] * kToRadians), cy = std::cos(angles[1] * kToRadians);
    float sr = std::sin(angles[2] * kToRadians), cr = std::cos(angles[2] * kToRadians);
    Basis b;
    b.forward = {cp * cy, cp * sy, -sp};
    b.right = {-sr * sp * cy + cr * sy, -sr * sp * sy - cr * cy, -sr * cp};
    b.up = {cr * sp * cy + sr * sy, cr * sp * sy - sr * cy, cr * cp};
    return b;
}

}  // namespace nq

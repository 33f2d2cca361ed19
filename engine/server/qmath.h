// Vector helpers for the server's game code, with Quake's conventions: angles are pitch, yaw,
// roll in degrees; AngleVectors gives forward, right and up.
#pragma once

#include <cmath>

#include "vm/vm.h"

namespace nq::server::qmath {

using vm::Vec3f;

inline Vec3f add(const Vec3f& a, const Vec3f& b) {
    return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
inline Vec3f sub(const Vec3f& a, const Vec3f& b) {
    return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
inline Vec3f scale(const Vec3f& a, float k) {
    return {a[0] * k, a[1] * k, a[2] * k};
}
inline Vec3f mad(const Vec3f& a, float k, const Vec3f& b) {
    return {a[0] + k * b[0], a[1] + k * b[1], a[2] + k * b[2]};
}
inline float dot(const Vec3f& a, const Vec3f& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline float length(const Vec3f& a) {
    return std::sqrt(dot(a, a));
}

struct Basis {
    Vec3f forward, right, up;
};

inline Basis angle_vectors(const Vec3f& angles) {
    constexpr float kToRad = float(M_PI / 180.0);
    const float sy = std::sin(angles[1] * kToRad), cy = std::cos(angles[1] * kToRad);
    const float sp = std::sin(angles[0] * kToRad), cp = std::cos(angles[0] * kToRad);
    const float sr = std::sin(angles[2] * kToRad), cr = std::cos(angles[2] * kToRad);
    Basis b;
    b.forward = {cp * cy, cp * sy, -sp};
    b.right = {-sr * sp * cy + cr * sy, -sr * sp * sy - cr * cy, -sr * cp};
    b.up = {cr * sp * cy + sr * sy, cr * sp * sy - sr * cy, cr * cp};
    return b;
}

// Quake's anglemod: an angle wrapped into [0, 360) on a 16-bit grid.
inline float angle_mod(float a) {
    if (!std::isfinite(a)) return 0;
    const int steps = int(std::fmod(double(a), 360.0) * (65536 / 360.0));
    return (360.0f / 65536) * float(steps & 65535);
}

}  // namespace nq::server::qmath

// Small vector and angle helpers in Quake's conventions, shared by the client and the server:
// angles are degrees as (pitch, yaw, roll), yaw 0 looks along +X, +Z is up, pitch positive
// looks down.
#pragma once

#include <array>
#include <cmath>

namespace nq {

using Vec3 = std::array<float, 3>;

inline Vec3 vadd(const Vec3& a, const Vec3& b) {
    return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
inline Vec3 vsub(const Vec3& a, const Vec3& b) {
    return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
inline Vec3 vscale(const Vec3& a, float s) {
    return {a[0] * s, a[1] * s, a[2] * s};
}
// a + s * b
inline Vec3 vmad(const Vec3& a, float s, const Vec3& b) {
    return {a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2]};
}
inline float vdot(const Vec3& a, const Vec3& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline float vlength(const Vec3& a) {
    return std::sqrt(vdot(a, a));
}

// Quake's AngleVectors: the view basis for (pitch, yaw, roll).
struct Basis {
    Vec3 forward{}, right{}, up{};
};
Basis angle_vectors(const Vec3& angles);

}  // namespace nq

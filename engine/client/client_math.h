// Small vector and angle helpers for the client, in Quake's conventions: angles are degrees as
// (pitch, yaw, roll); yaw 0 looks along +X, +Z is up.
#pragma once

#include <cmath>

#include "formats/server_message.h"

namespace nq {

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

// Scales `v` to unit length and returns its former length (0 leaves it untouched).
float normalize(Vec3& v);

// The signed difference `to - from` brought into [-180, 180): the short way round.
float angle_delta(float from, float to);
// Interpolates between two angles the short way round: 359 -> 1 passes through 0 (as 360).
float lerp_angle(float from, float to, float frac);
// An angle brought into [0, 360).
float angle_mod(float degrees);

struct Basis {
    Vec3 forward{}, right{}, up{};
};
// Quake's view basis for (pitch, yaw, roll): pitch positive looks down.
Basis angle_vectors(const Vec3& angles);

}  // namespace nq

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

}  // namespace nq

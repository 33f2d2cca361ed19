// The server's angle helper with Quake's own rounding (the vector helpers and AngleVectors are
// common/vec3_math.h, shared with the client).
#pragma once

#include <cmath>

#include "common/vec3_math.h"
#include "vm/vm.h"

namespace nq::server::qmath {

using vm::Vec3f;

// Quake's anglemod: an angle wrapped into [0, 360) on a 16-bit grid.
inline float angle_mod(float a) {
    if (!std::isfinite(a)) return 0;
    const int steps = int(std::fmod(double(a), 360.0) * (65536 / 360.0));
    return (360.0f / 65536) * float(steps & 65535);
}

}  // namespace nq::server::qmath

// The client's angle helpers, in Quake's conventions (the vector helpers and the view basis
// are common/vec3_math.h).
#pragma once

#include <cmath>

#include "common/vec3_math.h"
#include "formats/server_message.h"

namespace nq {

// Scales `v` to unit length and returns its former length (0 leaves it untouched).
float normalize(Vec3& v);

// The signed difference `to - from` brought into [-180, 180): the short way round.
float angle_delta(float from, float to);
// Interpolates between two angles the short way round: 359 -> 1 passes through 0 (as 360).
float lerp_angle(float from, float to, float frac);
// An angle brought into [0, 360).
float angle_mod(float degrees);

}  // namespace nq

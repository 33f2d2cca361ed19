#include "client/beams.h"

#include <cmath>
#include <numbers>

#include "client/client_math.h"

namespace nq {

bool Beams::start(int entity, int model, double time, const Vec3& start, const Vec3& end) {
    Beam* slot = nullptr;
    for (Beam& b : beams_) {
        if (b.entity == entity && b.model != 0) {
            slot = &b;
            break;
        }
    }
    if (!slot) {
        for (Beam& b : beams_) {
            if (b.model == 0 || b.end_time < time) {
                slot = &b;
                break;
            }
        }
    }
    if (!slot) return false;
    *slot = Beam{entity, model, time + kBeamLifetime, start, end};
    return true;
}

Vec3 beam_angles(const Vec3& d) {
    constexpr float kToDegrees = 180.0f / std::numbers::pi_v<float>;
    float pitch, yaw;
    if (d[0] == 0 && d[1] == 0) {
        yaw = 0;
        pitch = d[2] > 0 ? 90.0f : 270.0f;
    } else {
        yaw = std::trunc(std::atan2(d[1], d[0]) * kToDegrees);
        if (yaw < 0) yaw += 360;
        float horizontal = std::sqrt(d[0] * d[0] + d[1] * d[1]);
        pitch = std::trunc(std::atan2(d[2], horizontal) * kToDegrees);
        if (pitch < 0) pitch += 360;
    }
    return {pitch, yaw, 0};
}

void Beams::build_segments(double time, int view_entity, const Vec3& view_origin,
                           ClientRandom& random, TempEntityBuffer& out) {
    for (Beam& b : beams_) {
        if (b.model == 0 || b.end_time < time) continue;
        if (b.entity == view_entity) b.start = view_origin;  // the player's bolt follows them
        Vec3 direction = vsub(b.end, b.start);
        const Vec3 angles = beam_angles(direction);
        float remaining = normalize(direction);
        Vec3 at = b.start;
        while (remaining > 0) {
            float roll = static_cast<float>(random.rand15() % 360);
            if (!out.push({b.model, at, {angles[0], angles[1], roll}, 0})) return;
            at = vmad(at, kBeamSegmentLength, direction);
            remaining -= kBeamSegmentLength;
        }
    }
}

}  // namespace nq

#include "render/light_smoother.h"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace nq {

namespace {

glm::vec3 load3(const float v[3]) {
    return {v[0], v[1], v[2]};
}

void store3(const glm::vec3& v, float out[3]) {
    out[0] = v.x;
    out[1] = v.y;
    out[2] = v.z;
}

void blend3(float state[3], const float sampled[3], float t) {
    store3(glm::mix(load3(state), load3(sampled), t), state);
}

}  // namespace

glm::vec3 slerp_unit(const glm::vec3& from, const glm::vec3& to, float t) {
    const float cosine = std::clamp(glm::dot(from, to), -1.0f, 1.0f);
    const float angle = std::acos(cosine);
    if (angle < 1e-4f) return to;
    // The unit vector perpendicular to `from` in the plane toward `to`.
    glm::vec3 side = to - from * cosine;
    if (glm::length(side) < 1e-6f) {  // opposite: turn through any perpendicular
        side = std::fabs(from.z) < 0.9f ? glm::cross(from, glm::vec3(0, 0, 1))
                                        : glm::cross(from, glm::vec3(1, 0, 0));
    }
    side = glm::normalize(side);
    const float turned = angle * t;
    return from * std::cos(turned) + side * std::sin(turned);
}

void LightSmoother::update(const EntityLighting& sampled, float dt, EntityLighting& out) {
    if (!valid_) {
        state_ = sampled;
        valid_ = true;
    } else if (dt > 0.0f) {
        const float t = 1.0f - std::exp(-dt / kLightSmoothingSeconds);
        state_.ambient += (sampled.ambient - state_.ambient) * t;
        state_.directional += (sampled.directional - state_.directional) * t;
        store3(slerp_unit(load3(state_.direction), load3(sampled.direction), t), state_.direction);
        blend3(state_.color, sampled.color, t);
        for (int i = 0; i < 6; ++i) blend3(state_.ambient_cube[i], sampled.ambient_cube[i], t);
    }
    // The light list is LightListSmoother's: passed through as sampled.
    EntityLighting result = state_;
    result.num_lights = sampled.num_lights;
    result.sources = sampled.sources;
    out = result;
}

}  // namespace nq

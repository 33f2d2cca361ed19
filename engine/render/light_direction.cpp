#include "render/light_direction.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace nq {

namespace {

struct Candidate {
    const LightEntity* light = nullptr;
    float weight = 0.0f;
    float distance = 0.0f;
};

float smoothstep01(float x) {
    x = std::clamp(x, 0.0f, 1.0f);
    return x * x * (3.0f - 2.0f * x);
}

float style_scale(std::span<const float> lightstyles, uint32_t style) {
    return style < lightstyles.size() ? std::max(lightstyles[style], 0.0f) : 1.0f;
}

// Keeps the kMaxTracedLights heaviest candidates, heaviest first.
struct TopLights {
    std::array<Candidate, kMaxTracedLights> items{};
    int count = 0;

    void offer(const Candidate& c) {
        if (count == kMaxTracedLights && c.weight <= items[count - 1].weight) return;
        int at = count < kMaxTracedLights ? count++ : count - 1;
        while (at > 0 && items[at - 1].weight < c.weight) {
            items[at] = items[at - 1];
            --at;
        }
        items[at] = c;
    }
};

// Two unit vectors perpendicular to `dir` (itself a unit vector).
void perpendiculars(const glm::vec3& dir, glm::vec3& a, glm::vec3& b) {
    const glm::vec3 helper = std::fabs(dir.z) < 0.9f ? glm::vec3(0, 0, 1) : glm::vec3(1, 0, 0);
    a = glm::normalize(glm::cross(dir, helper));
    b = glm::cross(dir, a);
}

// Whether the trace from `from` gets to `to`, or to within kProbeSlack of it.
bool line_of_sight(const Bsp& bsp, const glm::vec3& from, const glm::vec3& to) {
    const BspTrace t = trace_hull(bsp, 0, {from.x, from.y, from.z}, {to.x, to.y, to.z});
    if (t.start_solid) return false;
    const float short_by = (1.0f - t.fraction) * glm::length(to - from);
    return short_by <= kProbeSlack;
}

// Fraction of the probe points around the light that the point sees; `dir` is the unit vector
// from the point toward the light.
float probe_visibility(const Bsp& bsp, const glm::vec3& point, const glm::vec3& light,
                       const glm::vec3& dir) {
    glm::vec3 a, b;
    perpendiculars(dir, a, b);
    const glm::vec3 probes[kVisibilityProbes] = {light, light + a * kProbeOffset,
                                                 light - a * kProbeOffset, light + b * kProbeOffset,
                                                 light - b * kProbeOffset};
    int seen = 0;
    for (const glm::vec3& p : probes) seen += line_of_sight(bsp, point, p) ? 1 : 0;
    return float(seen) / float(kVisibilityProbes);
}

glm::vec3 dlight_sum(const glm::vec3& point, DlightList dlights) {
    glm::vec3 sum(0.0f);
    for (uint32_t i = 0; dlights.first && i < dlights.count; ++i) {
        const nqr_dlight* d = nqr_at(nqr_dlight, dlights.first, i);
        const glm::vec3 to(d->origin[0] - point.x, d->origin[1] - point.y, d->origin[2] - point.z);
        const float distance = glm::length(to);
        if (distance < 1e-3f) continue;
        sum += to / distance * light_weight(d->radius, d->radius, distance);
    }
    return sum;
}

}  // namespace

float light_visibility(const Bsp& bsp, const glm::vec3& point, const glm::vec3& light) {
    const glm::vec3 to = light - point;
    const float distance = glm::length(to);
    if (distance < 1e-3f) return line_of_sight(bsp, point, light) ? 1.0f : 0.0f;
    return probe_visibility(bsp, point, light, to / distance);
}

float light_weight(float brightness, float reach, float distance) {
    if (!(brightness > 0.0f)) return 0.0f;
    const float range = std::min(reach, kMaxLightRange);
    const float fade = smoothstep01((range - distance) / (0.5f * range));
    const float soft = kLightDistanceSoftening * kLightDistanceSoftening;
    return brightness * fade / (distance * distance + soft);
}

glm::vec3 dominant_light_direction(const Bsp& bsp, std::span<const LightEntity> lights,
                                   const glm::vec3& point, std::span<const float> lightstyles,
                                   DlightList dlights, const VisibilityCache* traced) {
    TopLights top;
    for (const LightEntity& light : lights) {
        const float distance = glm::length(light.origin - point);
        if (distance < 1e-3f) continue;
        const float brightness = light.brightness * style_scale(lightstyles, light.style);
        const float weight = light_weight(brightness, light.reach(), distance);
        if (weight > 0.0f) top.offer({&light, weight, distance});
    }
    glm::vec3 sum(0.0f, 0.0f, kSkyWeight);
    for (int i = 0; i < top.count; ++i) {
        const Candidate& c = top.items[i];
        const glm::vec3 dir = (c.light->origin - point) / c.distance;
        const float* known = traced ? traced->find(uint32_t(c.light - lights.data())) : nullptr;
        sum +=
            dir * c.weight * (known ? *known : probe_visibility(bsp, point, c.light->origin, dir));
    }
    sum += dlight_sum(point, dlights);
    const float length = glm::length(sum);
    return length > 1e-12f ? sum / length : glm::vec3(0.0f, 0.0f, 1.0f);
}

}  // namespace nq

#include "render/entity_lights.h"

#include <algorithm>

namespace nq {

namespace {

constexpr float kNormalLevel = 128.0f;
constexpr float kFalloffScale = 128.0f;  // the light tools' distance unit of 1/x falloffs

float mean_of(const glm::vec3& c) {
    return (c.r + c.g + c.b) / 3.0f;
}

float style_scale(std::span<const float> lightstyles, uint32_t style) {
    return style < lightstyles.size() ? std::max(lightstyles[style], 0.0f) : 1.0f;
}

glm::vec3 dlight_tint(const nqr_dlight& d) {
    const glm::vec3 c(std::max(d.color[0], 0.0f), std::max(d.color[1], 0.0f),
                      std::max(d.color[2], 0.0f));
    const float peak = std::max({c.r, c.g, c.b});
    return peak > 0.0f ? c / peak : glm::vec3(1.0f);
}

// Keeps the N strongest offered, strongest first.
template <int N>
struct Strongest {
    std::array<LightContribution, N> items{};
    int count = 0;

    void offer(const LightContribution& c) {
        if (!(c.strength > 0.0f)) return;
        if (count == N && c.strength <= items[count - 1].strength) return;
        int at = count < N ? count++ : count - 1;
        while (at > 0 && items[at - 1].strength < c.strength) {
            items[at] = items[at - 1];
            --at;
        }
        items[at] = c;
    }
};

LightContribution entity_contribution(const LightEntity& light, uint32_t key,
                                      const glm::vec3& point, std::span<const float> lightstyles) {
    const float level = light_level(light, glm::length(light.origin - point)) *
                        style_scale(lightstyles, light.style);
    const glm::vec3 color = light.color * (level / kNormalLevel);
    return {key, light.origin, color, mean_of(color)};
}

LightContribution dlight_contribution(const nqr_dlight& d, uint32_t index, const glm::vec3& point) {
    const glm::vec3 origin(d.origin[0], d.origin[1], d.origin[2]);
    const float level = std::max(d.radius - glm::length(origin - point), 0.0f);
    const glm::vec3 color = dlight_tint(d) * (level / kNormalLevel);
    return {kDynamicLightKey | index, origin, color, mean_of(color)};
}

void store3(const glm::vec3& v, float out[3]) {
    out[0] = v.x;
    out[1] = v.y;
    out[2] = v.z;
}

}  // namespace

void keep_strongest(LightContributions& list, const LightContribution& light) {
    if (!(light.strength > 0.0f)) return;
    if (list.count == kMaxEntityLights && light.strength <= list.items[list.count - 1].strength) {
        return;
    }
    int at = list.count < kMaxEntityLights ? list.count++ : list.count - 1;
    while (at > 0 && list.items[at - 1].strength < light.strength) {
        list.items[at] = list.items[at - 1];
        --at;
    }
    list.items[at] = light;
}

float light_level(const LightEntity& light, float distance) {
    const float b = std::max(light.brightness, 0.0f);
    const float scaled = std::max(distance, 0.0f) * light.wait / kFalloffScale;
    switch (light.delay) {
        case 1:  // 1/x
            return scaled > 1.0f ? b / scaled : b;
        case 2:  // 1/x^2
            return scaled > 1.0f ? b / (scaled * scaled) : b;
        case 3:  // infinite
        case 4:  // local minimum
            return b;
        case 5:  // 1/(x + 1)^2
            return b / ((scaled + 1.0f) * (scaled + 1.0f));
        default:  // linear
            return std::max(b - std::max(distance, 0.0f) * light.wait, 0.0f);
    }
}

LightContributions strongest_lights(const Bsp& bsp, std::span<const LightEntity> lights,
                                    const glm::vec3& point, std::span<const float> lightstyles,
                                    DlightList dlights, VisibilityCache* traced) {
    Strongest<kMaxLightCandidates> candidates;
    for (size_t i = 0; i < lights.size(); ++i) {
        candidates.offer(entity_contribution(lights[i], uint32_t(i), point, lightstyles));
    }
    LightContributions best;
    for (int i = 0; i < candidates.count; ++i) {
        LightContribution c = candidates.items[i];
        // Occlusion only takes away: once the list is full of lights at least as strong as
        // this one unoccluded, no later candidate can get in (they come strongest first).
        if (best.count == kMaxEntityLights && best.items[best.count - 1].strength >= c.strength) {
            break;
        }
        const float visible = light_visibility(bsp, point, c.position);
        if (traced) traced->add(c.key, visible);
        c.color *= visible;
        c.strength = mean_of(c.color);
        keep_strongest(best, c);
    }
    for (uint32_t i = 0; dlights.first && i < dlights.count; ++i) {
        keep_strongest(best, dlight_contribution(*nqr_at(nqr_dlight, dlights.first, i), i, point));
    }
    return best;
}

void store_lights(const LightContributions& lights, EntityLighting& out) {
    out.num_lights = uint32_t(std::clamp(lights.count, 0, kMaxEntityLights));
    for (int i = 0; i < kMaxEntityLights; ++i) {
        nqr_light_source& s = out.sources[i];
        s = nqr_light_source{};
        s.size = sizeof(nqr_light_source);
        if (i >= lights.count) continue;
        store3(lights.items[i].position, s.position);
        store3(lights.items[i].color, s.color);
    }
}

}  // namespace nq

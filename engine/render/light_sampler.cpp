#include "render/light_sampler.h"

#include <algorithm>

#include "render/lightmap_probe.h"

namespace nq {

namespace {

constexpr float kNormalLevel = 128.0f;      // light units shown as the texture's own colours
constexpr float kMaxAmbientLevel = 128.0f;  // Quake's clamps against overbright models
constexpr float kMaxTotalLevel = 192.0f;
constexpr float kUnlitMapLevel = 255.0f;

// A dynamic light's colour scaled so its strongest channel is 1: the light's strength is its
// radius, the colour only tints it.
glm::vec3 dlight_tint(const nqr_dlight& d) {
    const glm::vec3 c(std::max(d.color[0], 0.0f), std::max(d.color[1], 0.0f),
                      std::max(d.color[2], 0.0f));
    const float peak = std::max({c.r, c.g, c.b});
    return peak > 0.0f ? c / peak : glm::vec3(1.0f);
}

// Quake's dynamic light at `point`: radius - distance where positive. `level` gets the plain
// sum (what Quake adds to the light level), `rgb` the tinted sum, weighted by the cosine
// between `axis` and the direction toward each light when an axis is given.
void add_dlights(const glm::vec3& point, DlightList dlights, const glm::vec3* axis, float* level,
                 glm::vec3& rgb) {
    for (uint32_t i = 0; dlights.first && i < dlights.count; ++i) {
        const nqr_dlight* d = nqr_at(nqr_dlight, dlights.first, i);
        const glm::vec3 to(d->origin[0] - point.x, d->origin[1] - point.y, d->origin[2] - point.z);
        const float distance = glm::length(to);
        const float add = d->radius - distance;
        if (!(add > 0.0f)) continue;
        float factor = 1.0f;
        if (axis && distance > 1e-3f) factor = std::max(0.0f, glm::dot(*axis, to) / distance);
        if (level) *level += add * factor;
        rgb += add * factor * dlight_tint(*d);
    }
}

float level_of(const glm::vec3& rgb) {
    return (rgb.r + rgb.g + rgb.b) / 3.0f;
}

glm::vec3 tint_of(const glm::vec3& rgb) {
    const float peak = std::max({rgb.r, rgb.g, rgb.b});
    return peak > 0.0f ? rgb / peak : glm::vec3(1.0f);
}

void store3(const glm::vec3& v, float out[3]) {
    out[0] = v.x;
    out[1] = v.y;
    out[2] = v.z;
}

void fill_fullbright(EntityLighting& out) {
    out.ambient = 1.0f;
    out.directional = 0.0f;
    store3({0, 0, 1}, out.direction);
    store3(glm::vec3(1.0f), out.color);
    for (auto& face : out.ambient_cube) store3(glm::vec3(1.0f), face);
    store_lights(LightContributions{}, out);
}

}  // namespace

LightSampler::LightSampler(const Bsp& bsp, std::span<const uint8_t> lighting_rgb,
                           std::vector<LightEntity> lights, const AmbientCubeField* field)
    : bsp_(bsp), rgb_(lighting_rgb), lights_(std::move(lights)), field_(field) {}

glm::vec3 LightSampler::light_point(const glm::vec3& point,
                                    std::span<const float> lightstyles) const {
    if (rgb_.empty()) return glm::vec3(kUnlitMapLevel);
    const glm::vec3 below = point - glm::vec3(0.0f, 0.0f, kLightPointDepth);
    const auto hit = first_surface_along(bsp_, point, below);
    return hit ? sample_lightmap(bsp_, rgb_, *hit, lightstyles) : glm::vec3(0.0f);
}

AmbientCube LightSampler::ambient_cube(const glm::vec3& point, const glm::vec3& fallback) const {
    AmbientCube cube;
    if (field_ && field_->cube_at(point, cube)) return cube;
    cube.faces.fill(fallback);
    return cube;
}

void LightSampler::sample(const EntityLightQuery& query, std::span<const float> lightstyles,
                          DlightList dlights, EntityLighting& out,
                          LightContributions* lights) const {
    out = EntityLighting{};
    if (lights) *lights = LightContributions{};
    if (query.fullbright) {
        fill_fullbright(out);
        return;
    }
    const glm::vec3 ground = light_point(query.origin, lightstyles);
    float level = level_of(ground);
    glm::vec3 total = ground;
    add_dlights(query.origin, dlights, nullptr, &level, total);
    level = std::max(level, query.minimum_level);
    const float ambient = std::min(level, kMaxAmbientLevel);
    const float shade = std::min(level, kMaxTotalLevel - ambient);
    out.ambient = ambient / kNormalLevel;
    out.directional = shade / kNormalLevel;
    VisibilityCache traced;
    const LightContributions strongest =
        strongest_lights(bsp_, lights_, query.origin, lightstyles, dlights, &traced);
    store3(dominant_light_direction(bsp_, lights_, query.origin, lightstyles, dlights, &traced),
           out.direction);
    store3(tint_of(total), out.color);
    const AmbientCube cube = ambient_cube(query.origin, ground);
    for (int i = 0; i < kCubeFaces; ++i) {
        glm::vec3 face = cube.faces[i];
        add_dlights(query.origin, dlights, &kCubeAxes[i], nullptr, face);
        store3(face / kNormalLevel, out.ambient_cube[i]);
    }
    store_lights(strongest, out);
    if (lights) *lights = strongest;
}

}  // namespace nq

#include "technical/shading_model.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "abi/abi_access.h"
#include "technical/shading_glsl.h"

namespace nq::npr::technical {
namespace {

glm::vec3 gooch_tone(const ShadingSettings& s, glm::vec3 kd, float n_dot_l) {
    const glm::vec3 cool = glm::vec3(0.0f, 0.0f, s.blue) + s.alpha * kd;
    const glm::vec3 warm = glm::vec3(s.yellow, s.yellow, 0.0f) + s.beta * kd;
    const float t = (1.0f + n_dot_l) * 0.5f;
    return t * cool + (1.0f - t) * warm;
}

glm::vec3 metal_tone(const ShadingSettings& s, glm::vec3 kd, float n_dot_l, float height) {
    const float band = 0.5f + 0.5f * std::sin(height * s.metal_bands * 0.0628318f);
    const glm::vec3 streaked = kd * glm::mix(0.55f, 1.15f, band);
    return glm::mix(streaked, glm::vec3(1.0f), 0.35f * std::max(n_dot_l, 0.0f));
}

}  // namespace

ToneLight tone_light(const nqr_entity& entity) {
    ToneLight out;
    out.object_color = object_id_color(entity.number);
    const nqr_entity_light& light = *entity.light;
    if (!npr::light_readable(&light)) return out;
    const glm::vec3 direction = glm::make_vec3(light.direction);
    const float length = glm::length(direction);
    if (length > 1e-6f) out.direction = direction / length;
    const bool fullbright = (entity.flags & NQR_ENTITY_FULLBRIGHT) != 0;
    out.ambient = fullbright ? 1.0f : light.ambient;
    out.directional = fullbright ? 0.0f : light.directional;
    out.color = glm::make_vec3(light.color);
    return out;
}

glm::vec3 technical_shade(const ShadingSettings& s, const ToneLight& light, glm::vec3 kd,
                          glm::vec3 n, float height) {
    if (s.mode == ShadingMode::object_id) return light.object_color;
    const float n_dot_l = std::clamp(glm::dot(n, light.direction), -1.0f, 1.0f);
    glm::vec3 color;
    if (s.mode == ShadingMode::classic) {
        color = kd * (light.ambient + light.directional * std::max(n_dot_l, 0.0f)) * light.color;
    } else if (s.mode == ShadingMode::metal) {
        color = metal_tone(s, kd, n_dot_l, height);
    } else {
        color = gooch_tone(s, kd, -n_dot_l);  // warm on the lit side, as the GLSL
    }
    if (s.splashback && s.splashback_alpha > 0.0f && s.mode != ShadingMode::classic) {
        const float a = s.splashback_alpha;
        color *= std::pow(a * std::abs(n_dot_l) + (1.0f - a), s.splashback_p);
    }
    return glm::clamp(color, 0.0f, 1.0f);
}

}  // namespace nq::npr::technical

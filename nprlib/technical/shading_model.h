// The technical tones on the CPU: the same formulas as shading_glsl.h's technical_shade, for
// work done per vertex on the CPU (the alias edge drawer shades each edge's ends here). Keep the
// two in step; nprlib_technical_shading_test compares them.
#pragma once

#include <glm/vec3.hpp>

#include "nqr_renderer.h"
#include "technical/technical_settings.h"

namespace nq::npr::technical {

// One entity's light, as set_entity_light_uniforms and the drawers' light direction give it.
struct ToneLight {
    glm::vec3 direction{0.0f, 0.0f, 1.0f};  // unit, toward the light (world)
    float ambient = 1.0f, directional = 0.0f;
    glm::vec3 color{1.0f};
    glm::vec3 object_color{1.0f};
};

ToneLight tone_light(const nqr_entity& entity);

// n: unit world normal; height: model-space z (metal bands).
glm::vec3 technical_shade(const ShadingSettings& settings, const ToneLight& light, glm::vec3 kd,
                          glm::vec3 n, float height);

}  // namespace nq::npr::technical

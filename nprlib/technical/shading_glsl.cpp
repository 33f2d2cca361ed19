#include "technical/shading_glsl.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <iterator>
#include <string>

namespace nq::npr::technical {

const char* const kShadingLibrary = R"(
uniform float u_gooch_b, u_gooch_y, u_gooch_alpha, u_gooch_beta;
uniform float u_splash_alpha, u_splash_p;
uniform float u_metal_bands, u_texture_blend;
uniform float u_ambient, u_directional;
uniform vec3 u_light_color;
uniform vec3 u_object_color;

// k_d: the skin's average (computed on the CPU, skin_tones.h), blended toward the texel.
vec3 surface_kd_from(vec3 average, vec3 texel) {
#if TEXTURE_BLEND
    return mix(average, texel, u_texture_blend);
#else
    return average;
#endif
}

vec3 gooch_tone(vec3 kd, float n_dot_l) {
    vec3 k_cool = vec3(0.0, 0.0, u_gooch_b) + u_gooch_alpha * kd;
    vec3 k_warm = vec3(u_gooch_y, u_gooch_y, 0.0) + u_gooch_beta * kd;
    float t = (1.0 + n_dot_l) * 0.5;
    return t * k_cool + (1.0 - t) * k_warm;
}

vec3 metal_tone(vec3 kd, float n_dot_l, float height) {
    // Anisotropic streaks (Gooch 99): bands of alternating lightness across the height,
    // the lit side pushed toward white.
    float band = 0.5 + 0.5 * sin(height * u_metal_bands * 0.0628318);
    vec3 streaked = kd * mix(0.55, 1.15, band);
    return mix(streaked, vec3(1.0), 0.35 * max(n_dot_l, 0.0));
}

vec3 technical_shade(vec3 kd, vec3 n, vec3 l, float height) {
#if SHADING_MODE == 3
    return u_object_color;
#else
    float n_dot_l = clamp(dot(n, l), -1.0, 1.0);
#if SHADING_MODE == 0
    vec3 color = kd * (u_ambient + u_directional * max(n_dot_l, 0.0)) * u_light_color;
#elif SHADING_MODE == 2
    vec3 color = metal_tone(kd, n_dot_l, height);
#else
    // l points toward the light and warm belongs on the lit side: t = (1 - n.l) / 2.
    vec3 color = gooch_tone(kd, -n_dot_l);
#endif
#if SPLASHBACK
    // Splash-back belongs to the technical tones; classic stays GLQuake's lighting.
    color *= pow(u_splash_alpha * abs(n_dot_l) + (1.0 - u_splash_alpha), u_splash_p);
#endif
    return clamp(color, 0.0, 1.0);
#endif
}
)";

int shading_variant(const ShadingSettings& s) {
    const bool splashback = s.splashback && s.splashback_alpha > 0.0f &&
                            s.mode != ShadingMode::classic && s.mode != ShadingMode::object_id;
    const bool blend = s.texture_blend > 0.0f && s.mode != ShadingMode::object_id;
    return static_cast<int>(s.mode) * 4 + (splashback ? 2 : 0) + (blend ? 1 : 0);
}

std::string shading_defines(int variant) {
    return "#define SHADING_MODE " + std::to_string(variant / 4) + "\n#define SPLASHBACK " +
           std::to_string((variant >> 1) & 1) + "\n#define TEXTURE_BLEND " +
           std::to_string(variant & 1) + "\n";
}

void set_shading_uniforms(gl::Program& program, const ShadingSettings& s) {
    glUniform1f(program.location("u_gooch_b"), s.blue);
    glUniform1f(program.location("u_gooch_y"), s.yellow);
    glUniform1f(program.location("u_gooch_alpha"), s.alpha);
    glUniform1f(program.location("u_gooch_beta"), s.beta);
    glUniform1f(program.location("u_splash_alpha"), s.splashback_alpha);
    glUniform1f(program.location("u_splash_p"), s.splashback_p);
    glUniform1f(program.location("u_metal_bands"), s.metal_bands);
    glUniform1f(program.location("u_texture_blend"), std::clamp(s.texture_blend, 0.0f, 1.0f));
}

glm::vec3 object_id_color(uint32_t entity_number) {
    // Components from {0, 128/255, 1} (exactly 128 in an 8-bit buffer), greys left out: 24
    // colours, the six pure ones first.
    constexpr float h = 128.0f / 255.0f;
    static constexpr glm::vec3 kColors[] = {
        {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {1, 0, 1}, {0, 1, 1}, {1, h, 0}, {1, 0, h},
        {h, 1, 0}, {0, 1, h}, {h, 0, 1}, {0, h, 1}, {h, 0, 0}, {0, h, 0}, {0, 0, h}, {h, h, 0},
        {h, 0, h}, {0, h, h}, {1, 1, h}, {1, h, 1}, {h, 1, 1}, {1, h, h}, {h, 1, h}, {h, h, 1}};
    return kColors[entity_number % std::size(kColors)];
}

void set_entity_light_uniforms(gl::Program& program, const nqr_entity& entity) {
    const glm::vec3 id = object_id_color(entity.number);
    glUniform3f(program.location("u_object_color"), id.x, id.y, id.z);
    const bool fullbright = (entity.flags & NQR_ENTITY_FULLBRIGHT) != 0;
    glUniform1f(program.location("u_ambient"), fullbright ? 1.0f : entity.light->ambient);
    glUniform1f(program.location("u_directional"), fullbright ? 0.0f : entity.light->directional);
    glUniform3f(program.location("u_light_color"), entity.light->color[0], entity.light->color[1],
                entity.light->color[2]);
}

}  // namespace nq::npr::technical

#include "illustrative/illustrative_glsl.h"

#include <epoxy/gl.h>

#include <algorithm>

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "classic/abi_access.h"
#include "illustrative/skin_masks.h"

namespace nq::npr::illustrative {

const char* const kIllustrativeLibrary = R"(
uniform sampler2D u_warp;
uniform vec3 u_cube[6];
uniform int u_num_lights;
uniform vec3 u_light_position[4];
uniform vec3 u_light_color[4];
uniform vec3 u_half_lambert;     // alpha, beta, gamma
uniform vec3 u_fresnel_ranges;
uniform vec4 u_phong;            // exponent, boost, rim exponent, rim boost
uniform vec4 u_terms;            // specular, per-light rim, dedicated rim, ambient scale
uniform vec3 u_mask_use;         // k_spec from the skin, k_r from the skin, exponent min
uniform float u_mask_exponent_span;
uniform int u_show;

vec3 ill_ambient_cube(vec3 n) {
    vec3 n2 = n * n;
    return n2.x * (n.x >= 0.0 ? u_cube[0] : u_cube[1]) +
           n2.y * (n.y >= 0.0 ? u_cube[2] : u_cube[3]) +
           n2.z * (n.z >= 0.0 ? u_cube[4] : u_cube[5]);
}
// Linear filtering by hand: two fetches are cheaper than a sampler's bilinear on software GL.
vec3 ill_warp(float x) {
    float texel = clamp(x * 256.0 - 0.5, 0.0, 255.0);
    int i0 = int(texel);
    vec3 w0 = texelFetch(u_warp, ivec2(i0, 0), 0).rgb;
    vec3 w1 = texelFetch(u_warp, ivec2(min(i0 + 1, 255), 0), 0).rgb;
    return 2.0 * mix(w0, w1, texel - float(i0));
}
float ill_half_lambert(float n_dot_l) {
    return pow(clamp(u_half_lambert.x * n_dot_l + u_half_lambert.y, 0.0, 1.0), u_half_lambert.z);
}
// Source's Fresnel ranges: (1 - n.v)^2 through (r0 facing, r1 middle, r2 grazing).
float ill_fresnel(float n_dot_v) {
    float f = 1.0 - clamp(n_dot_v, 0.0, 1.0);
    f *= f;
    return f > 0.5 ? mix(u_fresnel_ranges.y, u_fresnel_ranges.z, 2.0 * f - 1.0)
                   : mix(u_fresnel_ranges.x, u_fresnel_ranges.y, 2.0 * f);
}
vec3 ill_shade(vec3 kd, vec3 position, vec3 n, vec3 v, vec4 masks) {
    float n_dot_v = dot(n, v);
    float f_r = pow(1.0 - clamp(n_dot_v, 0.0, 1.0), 4.0);
    float f_s = ill_fresnel(n_dot_v);
    float k_s = masks.r;
    float k_spec = u_mask_use.x > 0.5 ? u_mask_use.z + masks.g * u_mask_exponent_span : u_phong.x;
    float k_r = u_mask_use.y > 0.5 ? masks.b : 1.0;
    vec3 ambient = u_terms.w * ill_ambient_cube(n);
    vec3 warped = vec3(0.0), specular = vec3(0.0), rim = vec3(0.0);
    float spec_scale = u_terms.x * f_s * u_phong.y;
    float rim_scale = u_terms.y * f_r * k_r * u_phong.w;
    for (int i = 0; i < u_num_lights; ++i) {
        vec3 l = normalize(u_light_position[i] - position);
        float n_dot_l = dot(n, l);
        warped += u_light_color[i] * ill_warp(ill_half_lambert(n_dot_l));
        float v_dot_r = max(dot(v, reflect(-l, n)), 0.0);
        float log_v_dot_r = log2(max(v_dot_r, 1e-8));  // one log for both powers
        float spec = spec_scale * exp2(k_spec * log_v_dot_r);
        float rim_i = rim_scale * exp2(u_phong.z * log_v_dot_r);
        // The paper's max(): the larger term wins per light; each is kept apart for ill_show.
        if (spec >= rim_i) specular += u_light_color[i] * k_s * spec;
        else rim += u_light_color[i] * k_s * rim_i;
    }
    float up = max(n.z, 0.0);
    rim += u_terms.z * up * f_r * k_r * u_phong.w * ill_ambient_cube(-v);
    vec3 diffuse = kd * (ambient + warped);
    if (u_show == 1) return kd;
    if (u_show == 2) return ambient;
    if (u_show == 3) return warped;
    if (u_show == 4) return diffuse;
    if (u_show == 5) return specular;
    if (u_show == 6) return rim;
    if (u_show == 7) return specular + rim;
    return diffuse + specular + rim;
}
)";

namespace {

glm::vec3 vec3_of(const float* v) {
    return glm::vec3(v[0], v[1], v[2]);
}

}  // namespace

ShaderLights shader_lights(const nqr_entity& entity, int max_lights) {
    ShaderLights out;
    const int limit = std::clamp(max_lights, 0, int(NQR_MAX_ENTITY_LIGHTS));
    if ((entity.flags & NQR_ENTITY_FULLBRIGHT) != 0) return out;
    const nqr_entity_light& light = entity.light;
    if (classic::light_has_sources(light) && light.num_lights > 0 &&
        light.lights[0].size >= sizeof(nqr_light_source)) {
        const int listed = std::min<int>(static_cast<int>(light.num_lights), limit);
        for (int i = 0; i < listed; ++i) {
            const nqr_light_source& source = classic::abi_element(light.lights, uint32_t(i));
            out.position[i] = vec3_of(source.position);
            out.color[i] = glm::max(vec3_of(source.color), glm::vec3(0.0f));
        }
        out.count = listed;
        return out;
    }
    // An older engine, or no local light: the dominant light, far away along its direction.
    constexpr float kFar = 1.0e5f;
    const glm::vec3 direction = vec3_of(light.direction);
    if (limit == 0 || glm::length(direction) < 1e-6f || !(light.directional > 0.0f)) return out;
    out.position[0] = vec3_of(entity.origin) + glm::normalize(direction) * kFar;
    out.color[0] = light.directional * vec3_of(light.color);
    out.count = 1;
    return out;
}

void set_illustrative_uniforms(gl::Program& program, const IllustrativeSettings& settings) {
    glUniform3f(program.location("u_half_lambert"), settings.half_lambert_alpha,
                settings.half_lambert_beta, settings.half_lambert_gamma);
    glUniform1i(program.location("u_show"), static_cast<int>(settings.show));
    glUniform1f(program.location("u_mask_exponent_span"), kMaxSpecularExponent - kMinSpecularExponent);
}

void set_entity_lighting(gl::Program& program, const nqr_entity& entity,
                         const MaterialParams& material, const IllustrativeSettings& settings) {
    const bool fullbright = (entity.flags & NQR_ENTITY_FULLBRIGHT) != 0;
    glm::vec3 cube[6];
    for (int face = 0; face < 6; ++face) {
        cube[face] = fullbright ? glm::vec3(1.0f) : vec3_of(entity.light.ambient_cube[face]);
    }
    glUniform3fv(program.location("u_cube"), 6, glm::value_ptr(cube[0]));
    ShaderLights lights = shader_lights(entity, settings.max_lights);
    for (int i = 0; i < lights.count; ++i) lights.color[i] *= settings.light_scale;
    glUniform1i(program.location("u_num_lights"), lights.count);
    if (lights.count > 0) {
        glUniform3fv(program.location("u_light_position"), lights.count,
                     glm::value_ptr(lights.position[0]));
        glUniform3fv(program.location("u_light_color"), lights.count,
                     glm::value_ptr(lights.color[0]));
    }
    glUniform3fv(program.location("u_fresnel_ranges"), 1, material.fresnel_ranges);
    glUniform4f(program.location("u_phong"), material.phong_exponent, material.phong_boost,
                material.rim_exponent, material.rim_boost);
    const float ambient = settings.ambient_scale * material.ambient_scale;
    glUniform4f(program.location("u_terms"), settings.specular ? 1.0f : 0.0f,
                settings.rim && material.rim_light ? 1.0f : 0.0f,
                settings.dedicated_rim && material.rim_light ? 1.0f : 0.0f, ambient);
    const bool skin_exponent = settings.skin_masks && material.exponent_from_skin;
    const bool skin_rim = settings.skin_masks && material.rim_mask;
    glUniform3f(program.location("u_mask_use"), skin_exponent ? 1.0f : 0.0f,
                skin_rim ? 1.0f : 0.0f, kMinSpecularExponent);
}

}  // namespace nq::npr::illustrative

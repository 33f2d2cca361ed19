#include "illustrative/illustrative_glsl.h"

#include <epoxy/gl.h>

#include <algorithm>

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "abi/abi_access.h"
#include "illustrative/skin_masks.h"

namespace nq::npr::illustrative {

const char* const kAmbientCubeLibrary = R"(
uniform vec3 u_cube[6];
vec3 ill_ambient_cube(vec3 n) {
    vec3 n2 = n * n;
    return n2.x * (n.x >= 0.0 ? u_cube[0] : u_cube[1]) +
           n2.y * (n.y >= 0.0 ? u_cube[2] : u_cube[3]) +
           n2.z * (n.z >= 0.0 ? u_cube[4] : u_cube[5]);
}
)";

const char* const kIllustrativeLibrary = R"(
// Compile-time switches (shading_defines()): software GL runs both sides of every branch and
// every iteration a uniform allows, so the common case is compiled without them.
//   ILL_LIGHTS n      this many lights, unrolled (absent: the uniform u_num_lights, up to 4)
//   ILL_GAMMA         the half-Lambert exponent gamma is applied (absent: gamma = 1)
//   ILL_SHOW_TERMS    the terms are kept apart for ill_show (absent: the final colour only)
//   ILL_CUTOUT        texels under the alpha cutoff are discarded (holey models); without a
//                     discard, software GL tests depth before shading, so hidden pixels are free
uniform sampler2D u_warp;
uniform vec3 u_light_position[4];
uniform vec3 u_light_color[4];
uniform vec3 u_half_lambert;     // alpha, beta, gamma
uniform vec3 u_fresnel_ranges;
uniform vec4 u_phong;            // exponent, boost, rim exponent, rim boost
uniform vec4 u_terms;            // specular, per-light rim, dedicated rim, ambient scale
uniform vec3 u_mask_use;         // k_spec from the skin, k_r from the skin, exponent min
uniform float u_mask_exponent_span;
#ifdef ILL_LIGHTS
#define ILL_LIGHT_COUNT ILL_LIGHTS
#else
uniform int u_num_lights;
#define ILL_LIGHT_COUNT u_num_lights
#endif
#ifdef ILL_SHOW_TERMS
uniform int u_show;
bool ill_final_colour() { return u_show == 0; }
#else
bool ill_final_colour() { return true; }
#endif

// Linear filtering by hand: two fetches are cheaper than a sampler's bilinear on software GL.
vec3 ill_warp(float x) {
    float texel = clamp(x * 256.0 - 0.5, 0.0, 255.0);
    int i0 = int(texel);
    vec3 w0 = texelFetch(u_warp, ivec2(i0, 0), 0).rgb;
    vec3 w1 = texelFetch(u_warp, ivec2(min(i0 + 1, 255), 0), 0).rgb;
    return 2.0 * mix(w0, w1, texel - float(i0));
}
float ill_half_lambert(float n_dot_l) {
    float h = clamp(u_half_lambert.x * n_dot_l + u_half_lambert.y, 0.0, 1.0);
#ifdef ILL_GAMMA
    h = pow(h, u_half_lambert.z);
#endif
    return h;
}
// Source's Fresnel ranges: (1 - n.v)^2 through (r0 facing, r1 middle, r2 grazing).
float ill_fresnel(float one_minus_n_dot_v) {
    float f = one_minus_n_dot_v * one_minus_n_dot_v;
    return f > 0.5 ? mix(u_fresnel_ranges.y, u_fresnel_ranges.z, 2.0 * f - 1.0)
                   : mix(u_fresnel_ranges.x, u_fresnel_ranges.y, 2.0 * f);
}
// The lit colour; `ambient_light` is the part of it the ambient cube gives (k_d a(n) and the
// dedicated rim), which ambient obscurance darkens.
vec3 ill_shade(vec3 kd, vec3 position, vec3 n, vec3 v, vec4 masks, vec3 cube_n, vec3 cube_back,
               out vec3 ambient_light) {
    float one_minus_n_dot_v = 1.0 - clamp(dot(n, v), 0.0, 1.0);
    float f_r = one_minus_n_dot_v * one_minus_n_dot_v;
    f_r *= f_r;
    float f_s = ill_fresnel(one_minus_n_dot_v);
    float k_s = masks.r;
    float k_spec = u_mask_use.x > 0.5 ? u_mask_use.z + masks.g * u_mask_exponent_span : u_phong.x;
    float k_r = u_mask_use.y > 0.5 ? masks.b : 1.0;
    vec3 ambient = u_terms.w * cube_n;
    vec3 warped = vec3(0.0), specular = vec3(0.0), rim = vec3(0.0);
    float spec_scale = u_terms.x * f_s * u_phong.y;
    float rim_scale = u_terms.y * f_r * k_r * u_phong.w;
    for (int i = 0; i < ILL_LIGHT_COUNT; ++i) {
        vec3 l = normalize(u_light_position[i] - position);
        float n_dot_l = dot(n, l);
        warped += u_light_color[i] * ill_warp(ill_half_lambert(n_dot_l));
        float v_dot_r = max(dot(v, reflect(-l, n)), 0.0);
        float log_v_dot_r = log2(max(v_dot_r, 1e-8));  // one log for both powers
        float spec = spec_scale * exp2(k_spec * log_v_dot_r);
        float rim_i = rim_scale * exp2(u_phong.z * log_v_dot_r);
#ifdef ILL_SHOW_TERMS
        // The paper's max(): the larger term wins per light; each is kept apart for ill_show.
        if (spec >= rim_i) specular += u_light_color[i] * k_s * spec;
        else rim += u_light_color[i] * k_s * rim_i;
#else
        specular += u_light_color[i] * (k_s * max(spec, rim_i));
#endif
    }
    float up = max(n.z, 0.0);
    vec3 dedicated_rim = u_terms.z * up * f_r * k_r * u_phong.w * cube_back;
    rim += dedicated_rim;
    ambient_light = kd * ambient + dedicated_rim;
    vec3 diffuse = kd * (ambient + warped);
#ifdef ILL_SHOW_TERMS
    if (u_show == 1) return kd;
    if (u_show == 2) return ambient;
    if (u_show == 3) return warped;
    if (u_show == 4) return diffuse;
    if (u_show == 5) return specular;
    if (u_show == 6) return rim;
    if (u_show == 7) return specular + rim;
#endif
    return diffuse + specular + rim;
}
// The share of a colour that is ambient light, for the G-buffer's normal alpha (the part the
// engine's obscurance darkens); a little above 0 so the pixel still counts as a surface.
float ill_ambient_share(vec3 ambient_light, vec3 colour) {
    const vec3 luma = vec3(0.299, 0.587, 0.114);
    float total = dot(colour, luma);
    return total > 1e-4 ? clamp(dot(ambient_light, luma) / total, 0.01, 1.0) : 1.0;
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
    const nqr_entity_light& light = *entity.light;
    if (npr::light_readable(&light) && light.num_lights > 0) {
        const int listed = std::min<int>(static_cast<int>(light.num_lights), limit);
        for (int i = 0; i < listed; ++i) {
            const nqr_light_source& source = npr::abi_element(light.lights, uint32_t(i));
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

ShadingVariant shading_variant(const IllustrativeSettings& settings, int lights, bool cutout) {
    if (settings.show != ShowTerm::final || cutout) return ShadingVariant{};
    ShadingVariant variant;
    variant.general = false;
    variant.lights = std::clamp(lights, 0, int(NQR_MAX_ENTITY_LIGHTS));
    variant.gamma = settings.half_lambert_gamma != 1.0f;
    return variant;
}

int variant_index(const ShadingVariant& variant) {
    if (variant.general) return kShadingVariants - 1;
    return 2 * std::clamp(variant.lights, 0, int(NQR_MAX_ENTITY_LIGHTS)) + (variant.gamma ? 1 : 0);
}

std::string shading_defines(const ShadingVariant& variant) {
    if (variant.general) return "#define ILL_SHOW_TERMS\n#define ILL_GAMMA\n#define ILL_CUTOUT\n";
    std::string defines = "#define ILL_LIGHTS " + std::to_string(variant.lights) + "\n";
    if (variant.gamma) defines += "#define ILL_GAMMA\n";
    return defines;
}

void set_illustrative_uniforms(gl::Program& program, const IllustrativeSettings& settings) {
    glUniform3f(program.location("u_half_lambert"), settings.half_lambert_alpha,
                settings.half_lambert_beta, settings.half_lambert_gamma);
    glUniform1i(program.location("u_show"), static_cast<int>(settings.show));
    glUniform1f(program.location("u_mask_exponent_span"),
                kMaxSpecularExponent - kMinSpecularExponent);
}

namespace {

// A light as the ambient cube holds it: each face gets the light's colour times the cosine
// between the face's axis and the direction toward the light, so a(n) is about c max(0, n.l).
void add_light_to_cube(glm::vec3 (&cube)[6], const glm::vec3& origin, const glm::vec3& position,
                       const glm::vec3& color) {
    const glm::vec3 offset = position - origin;
    const float length = glm::length(offset);
    if (!(length > 1e-6f)) return;
    const glm::vec3 toward = offset / length;
    for (int axis = 0; axis < 3; ++axis) {
        cube[2 * axis] += color * std::max(toward[axis], 0.0f);
        cube[2 * axis + 1] += color * std::max(-toward[axis], 0.0f);
    }
}

}  // namespace

EntityShading entity_shading(const nqr_entity& entity, const IllustrativeSettings& settings) {
    EntityShading out;
    const bool fullbright = (entity.flags & NQR_ENTITY_FULLBRIGHT) != 0;
    for (int face = 0; face < 6; ++face) {
        out.cube[face] = fullbright ? glm::vec3(1.0f) : vec3_of(entity.light->ambient_cube[face]);
    }
    ShaderLights all = shader_lights(entity, NQR_MAX_ENTITY_LIGHTS);
    const int per_pixel = std::min(all.count, std::clamp(settings.max_lights, 0, all.count));
    const glm::vec3 origin = vec3_of(entity.origin);
    for (int i = 0; i < all.count; ++i) {
        all.color[i] *= settings.light_scale;
        if (i >= per_pixel) add_light_to_cube(out.cube, origin, all.position[i], all.color[i]);
    }
    all.count = per_pixel;
    out.lights = all;
    return out;
}

void set_entity_lighting(gl::Program& program, const EntityShading& shading,
                         const MaterialParams& material, const IllustrativeSettings& settings) {
    glUniform3fv(program.location("u_cube"), 6, glm::value_ptr(shading.cube[0]));
    const ShaderLights& lights = shading.lights;
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
    glUniform3f(program.location("u_mask_use"), skin_exponent ? 1.0f : 0.0f, skin_rim ? 1.0f : 0.0f,
                kMinSpecularExponent);
}

}  // namespace nq::npr::illustrative

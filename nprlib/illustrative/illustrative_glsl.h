// GLSL for the illustrative style's model shading, the paper's equations 1 and 2 per pixel:
//
//   k_d [ a(n) + sum_i c_i w((alpha (n.l_i) + beta)^gamma) ] (view-independent)
// + sum_i c_i k_s max(f_s (v.r_i)^k_spec, f_r k_r (v.r_i)^k_rim) + (n.u) f_r k_r a(-v)
// (view-dependent)
//
// a(n) = sum n_i^2 C[sign n_i]: the entity's ambient cube (nqr_entity_light.ambient_cube);
// c_i, l_i: its local lights (ABI 1.4), or the sampled dominant light on an older engine;
// w(): the warp ramp texture, read x2 (overbright up to 2); f_r = (1 - n.v)^4; f_s: Source's
// Fresnel ranges, (1 - n.v)^2 mapped piecewise-linearly through (r0, r1, r2); u = world up;
// a(-v): the cube read along the view ray (light arriving from behind the model, so rims follow
// the light actually around it). Boosts multiply the specular and rim terms; k_s, k_spec, k_r
// come from the skin-mask texture (R, G, B) and A marks shirt/pants texels.
//
// Paste shading_defines() and kIllustrativeLibrary after the #version line;
// set_illustrative_uniforms() fills its per-pass uniforms, set_entity_lighting() its per-entity
// ones.
#pragma once

#include <string>

#include <glm/vec3.hpp>

#include "gl/program.h"
#include "illustrative/illustrative_settings.h"
#include "nqr_renderer.h"

namespace nq::npr::illustrative {

// Declares (GLSL) u_cube[6] and vec3 ill_ambient_cube(vec3 n). The cube is a quadratic in n
// and read per vertex (as Source's vertex-lit shaders do): it varies slowly over a model.
extern const char* const kAmbientCubeLibrary;

// Declares (GLSL): the uniforms below and, all in world space with unit n and v,
//   vec3 ill_shade(vec3 kd, vec3 position, vec3 n, vec3 v, vec4 masks,
//                  vec3 cube_n, vec3 cube_back)     cube_n = a(n), cube_back = a(-v)
//   bool ill_final_colour()   false while ill_show shows one term alone
extern const char* const kIllustrativeLibrary;

// The lights the shader gets for `entity`: ABI 1.4's list, or on an older engine (or an empty
// list) the dominant light, far along its direction. At most NQR_MAX_ENTITY_LIGHTS.
struct ShaderLights {
    int count = 0;
    glm::vec3 position[NQR_MAX_ENTITY_LIGHTS];
    glm::vec3 color[NQR_MAX_ENTITY_LIGHTS];
};
ShaderLights shader_lights(const nqr_entity& entity, int max_lights);

// Which compiled form of the library draws an entity: the final colour with a fixed light count
// (and gamma only when it is not 1), or the general form that loops over u_num_lights, keeps
// the terms apart for ill_show and cuts out holey models' texels. Both give the same colour.
struct ShadingVariant {
    bool general = true;  // ILL_SHOW_TERMS, u_num_lights, gamma applied, ILL_CUTOUT
    int lights = 0;       // ILL_LIGHTS when not general
    bool gamma = false;   // ILL_GAMMA when not general
};
inline constexpr int kShadingVariants = 2 * (NQR_MAX_ENTITY_LIGHTS + 1) + 1;
ShadingVariant shading_variant(const IllustrativeSettings& settings, int lights, bool cutout);
int variant_index(const ShadingVariant& variant);  // 0 .. kShadingVariants - 1, general last
std::string shading_defines(const ShadingVariant& variant);

// Per pass: half-Lambert, ill_show. The program must be in use.
void set_illustrative_uniforms(gl::Program& program, const IllustrativeSettings& settings);

// What one entity is lit by: its strongest ill_max_lights lights per pixel, and the ambient
// cube with the entity's other listed lights added to it (Source's way with lights past its
// per-pixel budget: each face gets c_i max(0, axis . l_i)); light colours scaled by ill_lights.
struct EntityShading {
    ShaderLights lights;
    glm::vec3 cube[6];
};
EntityShading entity_shading(const nqr_entity& entity, const IllustrativeSettings& settings);

// Per entity: its material terms, ambient cube and lights.
void set_entity_lighting(gl::Program& program, const EntityShading& shading,
                         const MaterialParams& material, const IllustrativeSettings& settings);

}  // namespace nq::npr::illustrative

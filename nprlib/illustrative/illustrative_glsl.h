// GLSL for the illustrative style's model shading, the paper's equations 1 and 2 per pixel:
//
//   k_d [ a(n) + sum_i c_i w((alpha (n.l_i) + beta)^gamma) ]                      (view-independent)
// + sum_i c_i k_s max(f_s (v.r_i)^k_spec, f_r k_r (v.r_i)^k_rim) + (n.u) f_r k_r a(-v)  (view-dependent)
//
// a(n) = sum n_i^2 C[sign n_i]: the entity's ambient cube (nqr_entity_light.ambient_cube);
// c_i, l_i: its local lights (ABI 1.4), or the sampled dominant light on an older engine;
// w(): the warp ramp texture, read x2 (overbright up to 2); f_r = (1 - n.v)^4; f_s: Source's
// Fresnel ranges, (1 - n.v)^2 mapped piecewise-linearly through (r0, r1, r2); u = world up;
// a(-v): the cube read along the view ray (light arriving from behind the model, so rims follow
// the light actually around it). Boosts multiply the specular and rim terms; k_s, k_spec, k_r
// come from the skin-mask texture (R, G, B) and A marks shirt/pants texels.
//
// Paste kIllustrativeLibrary after the #version line; set_illustrative_uniforms() fills its
// per-pass uniforms, set_entity_lighting() its per-entity ones.
#pragma once

#include <glm/vec3.hpp>

#include "gl/program.h"
#include "illustrative/illustrative_settings.h"
#include "nqr_renderer.h"

namespace nq::npr::illustrative {

// Declares (GLSL): the uniforms below and
//   vec3 ill_ambient_cube(vec3 n)
//   vec3 ill_shade(vec3 kd, vec3 position, vec3 n, vec3 v, vec4 masks)   world space, unit n, v
extern const char* const kIllustrativeLibrary;

// Per pass: half-Lambert, ill_show. The program must be in use.
void set_illustrative_uniforms(gl::Program& program, const IllustrativeSettings& settings);

// Per entity: its material terms, ambient cube and lights (scaled by the settings).
void set_entity_lighting(gl::Program& program, const nqr_entity& entity,
                         const MaterialParams& material, const IllustrativeSettings& settings);

// The lights the shader gets for `entity`: ABI 1.4's list, or on an older engine (or an empty
// list) the dominant light, far along its direction. At most NQR_MAX_ENTITY_LIGHTS.
struct ShaderLights {
    int count = 0;
    glm::vec3 position[NQR_MAX_ENTITY_LIGHTS];
    glm::vec3 color[NQR_MAX_ENTITY_LIGHTS];
};
ShaderLights shader_lights(const nqr_entity& entity, int max_lights);

}  // namespace nq::npr::illustrative

// GLSL for the technical style's surface tones, shared by the face drawers (per pixel) and the
// edge drawers (per vertex: white addition starts from the shaded colour under the edge):
//   - Gooch 98 cool-to-warm: I = t k_cool + (1 - t) k_warm with k_cool = (0, 0, b) + alpha k_d,
//     k_warm = (y, y, 0) + beta k_d; the paper writes t = (1 + l.n) / 2, here t = (1 - n.l) / 2
//     because l points toward the light and the warm tone belongs on the lit side;
//   - splash-back ("Technical Quake"): I *= (alpha_s |cos theta| + (1 - alpha_s))^p, cos = n.l
//     (Gooch and metal; classic stays unmodified);
//   - Gooch 99 metal: k_d streaked by bands across the model's height, brightened toward l;
//   - classic: GLQuake-like lit texture (ambient + directional), for comparison.
// k_d is the skin's average colour (its 1x1 mip level; the skin must be mipmapped) blended
// toward the texel itself by texture_blend. Paste kShadingLibrary after the #version line;
// set_shading_uniforms() fills it.
#pragma once

#include <cstdint>

#include <glm/vec3.hpp>

#include "gl/program.h"
#include "nqr_renderer.h"
#include "technical/technical_settings.h"

namespace nq::npr::technical {

// Declares (GLSL):
//   uniform int u_shading_mode;                         ShadingMode
//   uniform float u_gooch_b, u_gooch_y, u_gooch_alpha, u_gooch_beta;
//   uniform float u_splash_alpha, u_splash_p;           u_splash_alpha = 0: no splash-back
//   uniform float u_metal_bands, u_texture_blend;
//   uniform float u_ambient, u_directional;             the entity's light (classic mode)
//   uniform vec3 u_light_color;
//   uniform vec3 u_object_color;                        object_id mode: the entity's colour
//   vec3 surface_kd(sampler2D skin, vec2 uv, float lod)   k_d (lod < 0: implicit lod)
//   vec3 skin_average(sampler2D skin)                   its average part (one per skin: a
//                                                       vertex shader can pass it on flat)
//   vec3 surface_kd_from(vec3 average, sampler2D skin, vec2 uv, float lod)
//   vec3 technical_shade(vec3 kd, vec3 n, vec3 l, float height)
//       n, l unit vectors in one space (l toward the light); height: a coordinate across the
//       model (for metal bands), in model units.
extern const char* const kShadingLibrary;

// Shading settings and the entity's light (the program must be in use).
void set_shading_uniforms(gl::Program& program, const ShadingSettings& settings);
// Light and object-id colour of one entity.
void set_entity_light_uniforms(gl::Program& program, const nqr_entity& entity);

// The object_id mode's colour for an entity number: one of 24 saturated colours with components
// 0, 1/2 or 1 (exact values no lit Quake texture is likely to produce).
glm::vec3 object_id_color(uint32_t entity_number);

}  // namespace nq::npr::technical

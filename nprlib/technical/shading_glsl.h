// GLSL for the technical style's surface tones, per pixel on alias faces (shading_model.h is the
// same on the CPU, for edge ends: white addition starts from the shaded colour under the edge):
//   - Gooch 98 cool-to-warm: I = t k_cool + (1 - t) k_warm with k_cool = (0, 0, b) + alpha k_d,
//     k_warm = (y, y, 0) + beta k_d; the paper writes t = (1 + l.n) / 2, here t = (1 - n.l) / 2
//     because l points toward the light and the warm tone belongs on the lit side;
//   - splash-back ("Technical Quake"): I *= (alpha_s |cos theta| + (1 - alpha_s))^p, cos = n.l
//     (Gooch and metal; classic stays unmodified);
//   - Gooch 99 metal: k_d streaked by bands across the model's height, brightened toward l;
//   - classic: GLQuake-like lit texture (ambient + directional), for comparison.
// k_d is the skin's average colour (skin_tones.h, from the CPU) blended toward the texel itself
// by texture_blend. The mode, splash-back and texture blending are chosen when the program is
// compiled (a software rasteriser runs both sides of every branch, per pixel): paste
// shading_defines(shading_variant(settings)) and then kShadingLibrary after the #version line,
// one program per variant; set_shading_uniforms() fills the uniforms.
#pragma once

#include <cstdint>
#include <string>

#include <glm/vec3.hpp>

#include "gl/program.h"
#include "nqr_renderer.h"
#include "technical/technical_settings.h"

namespace nq::npr::technical {

// Declares (GLSL), given SHADING_MODE (a ShadingMode), SPLASHBACK and TEXTURE_BLEND (0/1):
//   uniform float u_gooch_b, u_gooch_y, u_gooch_alpha, u_gooch_beta;
//   uniform float u_splash_alpha, u_splash_p;
//   uniform float u_metal_bands, u_texture_blend;
//   uniform float u_ambient, u_directional;             the entity's light (classic mode)
//   uniform vec3 u_light_color;
//   uniform vec3 u_object_color;                        object_id mode: the entity's colour
//   vec3 surface_kd_from(vec3 average, vec3 texel)
//       k_d; average: SkinSample::average
//   vec3 technical_shade(vec3 kd, vec3 n, vec3 l, float height)
//       n, l unit vectors in one space (l toward the light); height: a coordinate across the
//       model (for metal bands), in model units.
extern const char* const kShadingLibrary;

// The compiled variant the settings need (0 .. kShadingVariants - 1), and its #defines.
inline constexpr int kShadingVariants = 16;
int shading_variant(const ShadingSettings& settings);
std::string shading_defines(int variant);

// Shading settings and the entity's light (the program must be in use).
void set_shading_uniforms(gl::Program& program, const ShadingSettings& settings);
// Light and object-id colour of one entity.
void set_entity_light_uniforms(gl::Program& program, const nqr_entity& entity);

// The object_id mode's colour for an entity number: one of 24 saturated colours with components
// 0, 1/2 or 1 (exact values no lit Quake texture is likely to produce).
glm::vec3 object_id_color(uint32_t entity_number);

}  // namespace nq::npr::technical

// GLSL shared by every edge drawer (alias-model edges, brush edges, back-face lines): turning an
// edge into a screen-space quad of constant pixel width, pulled toward the eye so visible edges
// win the depth test against their own faces while hidden ones stay hidden, and the edge colour
// rules (base colour, white addition, distance fade). Paste kEdgeGeometryLibrary into a geometry
// shader after its #version/layout lines; set its uniforms with set_edge_uniforms().
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

#include "gl/program.h"
#include "technical/technical_settings.h"

namespace nq::npr::technical {

// Edge kinds, as the GLSL constants EDGE_SILHOUETTE, EDGE_RIDGE, EDGE_VALLEY, EDGE_BACKFACE.
enum class EdgeKind { silhouette = 0, ridge = 1, valley = 2, backface = 3 };

// Stage-neutral GLSL, pasted first. Declares:
//   uniform mat4 u_projection;     view space -> clip space
//   uniform vec2 u_viewport;       pixels
//   uniform float u_width_scale;   viewport height / 480: widths are given at 480 lines
//   uniform float u_depth_offset;  share of its depth an edge is pulled toward the eye, on top
//                                  of twice its half width's world size (so the faces beside
//                                  a valley do not bury it); EDGE_BACKFACE quads are not pulled
//   uniform int u_color_mode;      EdgeColorMode
//   uniform float u_white_w;
//   uniform float u_fade_distance; <= 0: no distance fade
//   uniform vec3 u_edge_colors[4]; base colour per kind
//   uniform float u_edge_widths[4];
//   vec3 edge_color(int kind, vec3 shaded, float distance)
//       the colour of an edge of `kind` over a surface whose shaded colour is `shaded`, seen
//       from `distance` world units;
// and the quad's geometry: a segment (view space, GL axes: the eye at 0 looking down -Z),
// clipped to the near plane, u_edge_widths[kind] pixels wide, with square caps half a width
// long. The fragment input is `in vec3 g_color`.
extern const char* const kEdgeLibrary;

// After kEdgeLibrary in a geometry shader:
//   void emit_edge(vec3 view0, vec3 view1, vec3 color0, vec3 color1, int kind)
//       emits the quad (4 vertices, one strip) for the segment view0-view1.
extern const char* const kEdgeGeometryLibrary;

// After kEdgeLibrary in a vertex shader that draws each edge as a quad of 4 vertices, two at
// each end (corner 0 and 1: the two sides), each knowing its own end and the other:
//   vec4 edge_corner_at(vec3 own, vec3 other, int kind, int corner)
//       the clip position of that vertex (view-space ends). Seen from the other end the sides
//       swap, so the quad is (own 0, own 1, other 0, other 1) as a fan. An end cut by the near
//       plane keeps its own colour (the caller's); an edge wholly behind lands off screen.
extern const char* const kEdgeVertexLibrary;

// A fragment shader for the quads: writes g_color.
extern const char* const kEdgeFragment;

struct EdgeFrameUniforms {
    glm::mat4 projection{1.0f};
    glm::vec2 viewport{640.0f, 480.0f};
    float z_near = 4.0f;
};

// Sets every uniform kEdgeLibrary declares (the program must be in use).
void set_edge_uniforms(gl::Program& program, const EdgeSettings& settings,
                       const EdgeFrameUniforms& frame);

}  // namespace nq::npr::technical

#include "technical/edge_glsl.h"

#include <epoxy/gl.h>

#include <glm/gtc/type_ptr.hpp>

namespace nq::npr::technical {

// Stage-neutral: uniforms, colours, and the quad's corners.
const char* const kEdgeLibrary = R"(
#define EDGE_SILHOUETTE 0
#define EDGE_RIDGE 1
#define EDGE_VALLEY 2
#define EDGE_BACKFACE 3
uniform mat4 u_projection;
uniform vec2 u_viewport;
uniform float u_width_scale;
uniform float u_depth_offset;
uniform float u_z_near;
uniform int u_color_mode;
uniform float u_white_w;
uniform float u_fade_distance;
uniform vec3 u_edge_colors[4];
uniform float u_edge_widths[4];

vec3 edge_color(int kind, vec3 shaded, float distance) {
    vec3 color = u_edge_colors[kind];
    bool white_here = u_color_mode == 2 ? kind != EDGE_BACKFACE
                                        : u_color_mode == 1 && (kind == EDGE_RIDGE || kind == EDGE_VALLEY);
    if (white_here) {
        color = kind == EDGE_VALLEY ? shaded * (1.0 - u_white_w)
                                    : min(shaded + vec3(u_white_w), vec3(1.0));
    }
    if (u_fade_distance > 0.0) color = mix(color, shaded, clamp(distance / u_fade_distance, 0.0, 1.0));
    return color;
}

// Pulled toward the eye by u_depth_offset of its depth, plus EDGE_WIDTH_PULL times the
// world size of its half width: a quad keeps its centre line's depth across its width, so
// without the second term the faces beside a valley (or inside a silhouette) that rise toward
// the eye would bury it. Back-face lines stay at their own depth: the front faces must hide
// them everywhere but beyond the outline.
#define EDGE_WIDTH_PULL 2.0
float pull_share(int kind, float half_width) {
    if (kind == EDGE_BACKFACE) return 0.0;
    // World units per pixel at depth d: d * 2 / (projection[1][1] * viewport height).
    float pixel_share = 2.0 / (u_projection[1][1] * u_viewport.y);
    return min(u_depth_offset + EDGE_WIDTH_PULL * half_width * pixel_share, 0.25);
}

vec4 pulled_clip(vec3 view_position, float pull) {
    return u_projection * vec4(view_position * (1.0 - pull), 1.0);
}

float edge_half_width(int kind) { return 0.5 * u_edge_widths[kind] * u_width_scale; }

// Clips the segment view0-view1 (view space, GL axes: the eye at 0 looking down -Z) to the
// near plane where it lies once pulled; t0/t1 say where the ends moved to along the segment
// (for their colours). False when nothing of it is in front of the eye.
bool clip_edge(inout vec3 view0, inout vec3 view1, float pull, out float t0, out float t1) {
    float limit = -u_z_near * 1.001 / (1.0 - pull);
    bool in0 = view0.z <= limit, in1 = view1.z <= limit;
    t0 = 0.0;
    t1 = 1.0;
    if (!in0 && !in1) return false;
    if (!in0 || !in1) {
        float t = (limit - view0.z) / (view1.z - view0.z);
        vec3 cut = mix(view0, view1, t);
        if (!in0) { view0 = cut; t0 = t; } else { view1 = cut; t1 = t; }
    }
    return true;
}

vec4 offset_clip(vec4 c, vec2 offset) { return vec4(c.xy + offset * c.w, c.zw); }

// Corner `corner` of the quad from c0 to c1: 0 and 1 at c0, 2 and 3 at c1; even corners on one
// side, odd on the other; square caps half a width long.
vec4 edge_corner(vec4 c0, vec4 c1, float half_width, int corner) {
    vec2 s0 = c0.xy / c0.w * 0.5 * u_viewport, s1 = c1.xy / c1.w * 0.5 * u_viewport;
    vec2 along = s1 - s0;
    float len = length(along);
    along = len > 1e-4 ? along / len : vec2(1.0, 0.0);
    // Pixel offsets back to clip space: multiply by w and divide by the half viewport.
    vec2 to_ndc = 2.0 / u_viewport;
    vec2 side = vec2(-along.y, along.x) * half_width * to_ndc;
    vec2 cap = along * half_width * to_ndc;
    vec2 sideways = (corner & 1) == 0 ? -side : side;
    return corner < 2 ? offset_clip(c0, sideways - cap) : offset_clip(c1, sideways + cap);
}
)";

// Geometry stage: emit_edge() writes one quad.
const char* const kEdgeGeometryLibrary = R"(
out vec3 g_color;
void emit_edge(vec3 view0, vec3 view1, vec3 color0, vec3 color1, int kind) {
    float half_width = edge_half_width(kind);
    float pull = pull_share(kind, half_width);
    float t0, t1;
    if (!clip_edge(view0, view1, pull, t0, t1)) return;
    vec3 from = mix(color0, color1, t0), to = mix(color0, color1, t1);
    vec4 c0 = pulled_clip(view0, pull), c1 = pulled_clip(view1, pull);
    for (int corner = 0; corner < 4; ++corner) {
        g_color = corner < 2 ? from : to;
        gl_Position = edge_corner(c0, c1, half_width, corner);
        EmitVertex();
    }
    EndPrimitive();
}
)";

// Vertex stage: each vertex is one corner of an edge's quad.
const char* const kEdgeVertexLibrary = R"(
out vec3 g_color;
// This vertex's clip position: side `corner` (0 or 1) at the end `own`, the edge running to
// `other` (view space). Off screen when nothing of the edge is in front of the eye.
vec4 edge_corner_at(vec3 own, vec3 other, int kind, int corner) {
    float half_width = edge_half_width(kind);
    float pull = pull_share(kind, half_width);
    float t0, t1;
    if (!clip_edge(own, other, pull, t0, t1)) return vec4(2.0, 2.0, 2.0, 1.0);
    return edge_corner(pulled_clip(own, pull), pulled_clip(other, pull), half_width, corner);
}
)";

const char* const kEdgeFragment = R"(#version 330 core
in vec3 g_color;
layout(location = 0) out vec4 o_color;
void main() { o_color = vec4(g_color, 1.0); }
)";

namespace {

glm::vec3 kind_color(const EdgeSettings& s, int kind) {
    switch (kind) {
        case 0:
            return s.silhouette_color;
        case 1:
            return s.ridge_color;
        case 2:
            return s.valley_color;
        default:
            return s.silhouette_color;  // back-face lines stand in for silhouettes
    }
}

}  // namespace

void set_edge_uniforms(gl::Program& program, const EdgeSettings& settings,
                       const EdgeFrameUniforms& frame) {
    glUniformMatrix4fv(program.location("u_projection"), 1, GL_FALSE,
                       glm::value_ptr(frame.projection));
    glUniform2f(program.location("u_viewport"), frame.viewport.x, frame.viewport.y);
    glUniform1f(program.location("u_width_scale"), frame.viewport.y / 480.0f);
    glUniform1f(program.location("u_depth_offset"), settings.depth_offset);
    glUniform1f(program.location("u_z_near"), frame.z_near);
    glUniform1i(program.location("u_color_mode"), static_cast<int>(settings.color_mode));
    glUniform1f(program.location("u_white_w"), settings.white_w);
    glUniform1f(program.location("u_fade_distance"),
                settings.distance_fade ? settings.fade_distance : 0.0f);
    float colors[12];
    for (int kind = 0; kind < 4; ++kind) {
        glm::vec3 c = kind_color(settings, kind);
        colors[kind * 3 + 0] = c.x;
        colors[kind * 3 + 1] = c.y;
        colors[kind * 3 + 2] = c.z;
    }
    glUniform3fv(program.location("u_edge_colors"), 4, colors);
    const float widths[4] = {settings.silhouette_width, settings.ridge_width, settings.valley_width,
                             settings.backface_width};
    glUniform1fv(program.location("u_edge_widths"), 4, widths);
}

}  // namespace nq::npr::technical

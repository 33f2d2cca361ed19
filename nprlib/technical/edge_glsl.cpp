#include "technical/edge_glsl.h"

#include <epoxy/gl.h>

#include <glm/gtc/type_ptr.hpp>

namespace nq::npr::technical {

const char* const kEdgeGeometryLibrary = R"(
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
out vec3 g_color;

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

void emit_edge(vec3 view0, vec3 view1, vec3 color0, vec3 color1, int kind) {
    float half_width = 0.5 * u_edge_widths[kind] * u_width_scale;
    float pull = pull_share(kind, half_width);
    // Clip to the near plane (view space looks down -Z), where it lies once pulled.
    float limit = -u_z_near * 1.001 / (1.0 - pull);
    bool in0 = view0.z <= limit, in1 = view1.z <= limit;
    if (!in0 && !in1) return;
    if (!in0 || !in1) {
        float t = (limit - view0.z) / (view1.z - view0.z);
        vec3 cut = mix(view0, view1, t);
        vec3 cut_color = mix(color0, color1, t);
        if (!in0) { view0 = cut; color0 = cut_color; } else { view1 = cut; color1 = cut_color; }
    }
    vec4 c0 = pulled_clip(view0, pull), c1 = pulled_clip(view1, pull);
    vec2 s0 = c0.xy / c0.w * 0.5 * u_viewport, s1 = c1.xy / c1.w * 0.5 * u_viewport;
    vec2 along = s1 - s0;
    float len = length(along);
    along = len > 1e-4 ? along / len : vec2(1.0, 0.0);
    vec2 across = vec2(-along.y, along.x);
    // Pixel offsets back to clip space: multiply by w and divide by the half viewport.
    vec2 to_ndc = 2.0 / u_viewport;
    vec2 side = across * half_width * to_ndc, cap = along * half_width * to_ndc;
    g_color = color0;
    gl_Position = vec4(c0.xy + (-cap - side) * c0.w, c0.zw); EmitVertex();
    g_color = color0;
    gl_Position = vec4(c0.xy + (-cap + side) * c0.w, c0.zw); EmitVertex();
    g_color = color1;
    gl_Position = vec4(c1.xy + (cap - side) * c1.w, c1.zw); EmitVertex();
    g_color = color1;
    gl_Position = vec4(c1.xy + (cap + side) * c1.w, c1.zw); EmitVertex();
    EndPrimitive();
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

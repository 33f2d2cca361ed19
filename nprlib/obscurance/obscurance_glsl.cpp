#include "obscurance/obscurance_glsl.h"

namespace nq::npr::obscurance {

const char* const kFullscreenVertex = R"(#version 330 core
out vec2 v_uv;
void main() {
    vec2 corner = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
    v_uv = corner;
    gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
)";

const char* const kSceneLibrary = R"(
uniform sampler2D u_depth;
uniform sampler2D u_normal;
uniform vec4 u_projection;  // P[0][0], P[1][1], P[2][2], P[3][2] of a symmetric perspective
uniform ivec2 u_scene_size;
ivec2 scene_texel(vec2 uv) {
    return clamp(ivec2(uv * vec2(u_scene_size)), ivec2(0), u_scene_size - 1);
}
// Distance along the view axis (positive) of the depth buffer's surface at a texel.
float scene_distance(ivec2 texel) {
    float ndc_z = texelFetch(u_depth, texel, 0).r * 2.0 - 1.0;
    return u_projection.w / (ndc_z + u_projection.z);
}
// View-space normal and whether the texel holds a surface that receives obscurance (alpha 1;
// the sky, the clear colour and liquids write 0).
vec4 scene_normal(ivec2 texel) {
    vec4 encoded = texelFetch(u_normal, texel, 0);
    return vec4(encoded.xyz * 2.0 - 1.0, encoded.a);
}
vec3 view_position(vec2 uv, float distance) {
    vec2 ndc = uv * 2.0 - 1.0;
    return vec3(ndc.x * distance / u_projection.x, ndc.y * distance / u_projection.y, -distance);
}
vec2 project(vec3 view) {
    float distance = max(-view.z, 1e-3);
    return vec2(u_projection.x * view.x, u_projection.y * view.y) / distance * 0.5 + 0.5;
}
)";

const char* const kEstimateFragment = R"(
in vec2 v_uv;
uniform vec2 u_radii;       // R and the second radius (0 = none)
uniform int u_dual_minimum;
uniform float u_thickness;  // 0 = infinitely thick
uniform int u_normal_clamp;
#ifdef VO_LINES
#define VO_COUNT VO_LINES
uniform vec3 u_samples[VO_COUNT];  // x, y on the unit disk, weight
#else
#define VO_COUNT VO_POINTS
uniform vec4 u_samples[VO_COUNT];  // x, y, z in the unit ball, weight
#endif
layout(location = 0) out float o_open;

// The open part [lo, min(t_scene, limit)] of a line, plus what lies behind a shell T deep.
float open_length(float t_scene, float lo, float limit) {
    float open_len = clamp(t_scene, lo, limit) - lo;
    if (u_thickness > 0.0) open_len += limit - clamp(t_scene + u_thickness, lo, limit);
    return open_len;
}

#ifdef VO_LINES
float open_fraction(vec3 p, vec3 n, float radius, mat2 rotation, float reflection) {
    float t_p = -p.z;
    float open_sum = 0.0, available_sum = 0.0;
    for (int i = 0; i < VO_COUNT; ++i) {
        vec2 s = rotation * vec2(u_samples[i].x * reflection, u_samples[i].y);
        float z_s = radius * sqrt(max(1.0 - dot(s, s), 1e-4));
        // The line runs along the view ray of the depth texel under the offset point, as the
        // depth buffer does: the texel's own ray, so a flat surface meets its tangent plane.
        ivec2 texel = scene_texel(project(vec3(p.xy + radius * s, p.z)));
        vec3 ray = view_position((vec2(texel) + 0.5) / vec2(u_scene_size), 1.0);
        float t_scene = scene_distance(texel);
        float lo = t_p - z_s, hi = t_p + z_s;
        // Where the ray passes behind the tangent plane (the camera is in front of it).
        float n_dot_ray = dot(n, ray);
        float limit =
            u_normal_clamp != 0 && n_dot_ray < -1e-6 ? clamp(dot(n, p) / n_dot_ray, lo, hi) : hi;
        float weight = u_samples[i].z / (2.0 * z_s);
        open_sum += weight * open_length(t_scene, lo, limit);
        available_sum += weight * (limit - lo);
    }
    if (u_normal_clamp == 0) return clamp(2.0 * open_sum, 0.0, 1.0);
    return available_sum > 1e-4 ? clamp(open_sum / available_sum, 0.0, 1.0) : 1.0;
}
#else
float open_fraction(vec3 p, vec3 n, float radius, mat2 rotation, float reflection) {
    float open_sum = 0.0;
    // Points on the tangent plane of a flat surface stay open, also where a texel's depth
    // spans a long stretch of a surface seen at a grazing angle.
    float bias = 0.02 * radius + 0.004 * -p.z;
    for (int i = 0; i < VO_COUNT; ++i) {
        vec3 s = vec3(rotation * u_samples[i].xy, u_samples[i].z * reflection);
        if (u_normal_clamp != 0 && dot(s, n) < 0.0) s = -s;
        vec3 x = p + radius * s;
        float behind = -x.z - scene_distance(scene_texel(project(x)));
        bool occluded = behind > bias && (u_thickness <= 0.0 || behind < u_thickness);
        open_sum += occluded ? 0.0 : u_samples[i].w;
    }
    return u_normal_clamp != 0 ? open_sum : clamp(2.0 * open_sum, 0.0, 1.0);
}
#endif

// A 4x4 ordered (Bayer) pattern of 16 rotations, every other one reflected.
const int kBayer[16] = int[16](0, 8, 2, 10, 12, 4, 14, 6, 3, 11, 1, 9, 15, 7, 13, 5);
void pixel_pattern(out mat2 rotation, out float reflection) {
    ivec2 q = ivec2(gl_FragCoord.xy) & 3;
    int bayer = kBayer[q.y * 4 + q.x];
    float angle = (float(bayer) + 0.5) * (6.2831853 / 16.0);
    float c = cos(angle), s = sin(angle);
    rotation = mat2(c, s, -s, c);
    reflection = (bayer & 1) == 0 ? 1.0 : -1.0;
}

void main() {
    ivec2 texel = scene_texel(v_uv);
    vec4 normal = scene_normal(texel);
    if (normal.a < 0.5) {
        o_open = 1.0;
        return;
    }
    float distance = scene_distance(texel);
    // A sphere smaller than a pixel has nothing the depth buffer can resolve.
    float radius_pixels = u_radii.x * u_projection.x / distance * 0.5 * float(u_scene_size.x);
    if (radius_pixels < 1.0) {
        o_open = 1.0;
        return;
    }
    vec3 p = view_position(v_uv, distance);
    vec3 n = normalize(normal.xyz);
    mat2 rotation;
    float reflection;
    pixel_pattern(rotation, reflection);
    float open = open_fraction(p, n, u_radii.x, rotation, reflection);
    if (u_radii.y > 0.0) {
        float second = open_fraction(p, n, u_radii.y, rotation, reflection);
        open = u_dual_minimum != 0 ? min(open, second) : open * second;
    }
    o_open = open;
}
)";

const char* const kBlurFragment = R"(
in vec2 v_uv;
uniform sampler2D u_open;
uniform ivec2 u_step;  // (1, 0) or (0, 1)
layout(location = 0) out float o_open;
const float kGauss[5] = float[5](0.2270270, 0.1945946, 0.1216216, 0.0540541, 0.0162162);
void main() {
    ivec2 size = textureSize(u_open, 0);
    ivec2 centre = clamp(ivec2(v_uv * vec2(size)), ivec2(0), size - 1);
    ivec2 scene_centre = scene_texel((vec2(centre) + 0.5) / vec2(size));
    vec4 n0 = scene_normal(scene_centre);
    if (n0.a < 0.5) {
        o_open = 1.0;
        return;
    }
    float t0 = scene_distance(scene_centre);
    float sum = 0.0, weights = 0.0;
    for (int k = -4; k <= 4; ++k) {
        ivec2 q = clamp(centre + k * u_step, ivec2(0), size - 1);
        ivec2 scene_q = scene_texel((vec2(q) + 0.5) / vec2(size));
        vec4 n = scene_normal(scene_q);
        float depth_weight = max(0.0, 1.0 - abs(scene_distance(scene_q) - t0) / (0.03 * t0));
        float normal_weight = pow(max(dot(n.xyz, n0.xyz), 0.0), 8.0) * step(0.5, n.a);
        float w = kGauss[abs(k)] * depth_weight * normal_weight;
        sum += w * texelFetch(u_open, q, 0).r;
        weights += w;
    }
    o_open = weights > 1e-5 ? sum / weights : texelFetch(u_open, centre, 0).r;
}
)";

const char* const kCompositeFragment = R"(#version 330 core
in vec2 v_uv;
uniform sampler2D u_open;
uniform float u_strength;
layout(location = 0) out vec4 o_color;
void main() {
    float open = texture(u_open, v_uv).r;
    o_color = vec4(vec3(mix(1.0, open, u_strength)), 1.0);
}
)";

}  // namespace nq::npr::obscurance

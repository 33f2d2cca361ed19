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
// Distances beyond this are all "far" in the moments (float precision of distance^2).
#define VO_MOMENTS_FAR 4096.0
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
// View-space normal and the share of the texel's colour that obscurance darkens (alpha: 1 for
// all of it, a style's ambient share where it keeps ambient light apart; the sky, the clear
// colour and liquids write 0).
bool receives(vec4 normal) { return normal.a > 0.002; }
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

const char* const kEstimate = R"(
uniform ivec2 u_target_size;  // the estimate's resolution (the scene's, or half of it)
uniform vec2 u_radii;       // R and the second radius (0 = none)
uniform int u_dual_minimum;
uniform float u_thickness;  // 0 = infinitely thick
uniform int u_normal_clamp;
uniform int u_shift;  // vo_shift: the pixel's pattern shifts the samples as well as turning them
// How a pixel turns, mirrors and shifts the sample set (pixel_pattern, below).
struct Pattern {
    mat2 rotation;
    float reflection;  // 1, or -1 to mirror the set
    vec2 shift;        // in [0, 1): through the volume's share (x) and, for points, height (y)
};
#if defined(VO_LINES)
#define VO_COUNT VO_LINES
// x, y on the unit disk, sqrt(1 - x^2 - y^2), Voronoi weight / (2 sqrt(1 - x^2 - y^2))
uniform vec4 u_samples[VO_COUNT];
// For the shift: the unit direction of x, y (any for the centre), the share of the sphere's
// volume in the columns nearer the centre, 1 - (1 - r^2)^(3/2), and half the weight.
uniform vec4 u_polar[VO_COUNT];
#elif defined(VO_POINTS)
#define VO_COUNT VO_POINTS
uniform vec4 u_samples[VO_COUNT];  // x, y, z in the unit ball, weight
// For the shift: the unit direction of x, y (any on the axis), the share of the ball's volume
// nearer the centre (r^3), and the height z / r on the unit sphere.
uniform vec4 u_polar[VO_COUNT];
#elif defined(VO_AREA)
uniform sampler2D u_moments;  // (distance, distance^2) of the depth buffer, mipmapped
uniform vec2 u_moments_scale;  // scene size / the moments texture's (padded) size
#endif
// The open part [lo, min(t_scene, limit)] of a line, plus what lies behind a shell T deep.
float open_length(float t_scene, float lo, float limit) {
    float open_len = clamp(t_scene, lo, limit) - lo;
    if (u_thickness > 0.0) open_len += limit - clamp(t_scene + u_thickness, lo, limit);
    return open_len;
}

#if defined(VO_LINES) || defined(VO_REFERENCE)
// One line through the sphere at s on the unit disk: its open and its available length (the
// part above the tangent plane with the clamp, else all 2 z_s of it).
// column = sqrt(1 - |s|^2), the line's half-length on the unit sphere.
void line_lengths(vec3 p, vec3 n, float radius, vec2 s, float column, out float open_len,
                  out float available) {
    float t_p = -p.z;
    float z_s = radius * column;
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
    open_len = open_length(t_scene, lo, limit);
    available = limit - lo;
}
// Open over available volume with the clamp; without it, a flat surface has half its sphere
// behind it, so the open share of the whole sphere is doubled.
float line_result(float open_sum, float available_sum, float volume_sum) {
    if (u_normal_clamp == 0) return clamp(2.0 * open_sum / volume_sum, 0.0, 1.0);
    return available_sum > 1e-4 * volume_sum ? clamp(open_sum / available_sum, 0.0, 1.0) : 1.0;
}
#endif

#if defined(VO_LINES)
// Line i where the pattern puts it: s on the unit disk, its column's half-length and its
// weight per unit of length. Shifted, the volume's share v moves round [0, 1) and the radius
// follows: 1 - r^2 = (1 - v)^(2/3), so the column is (1 - v)^(1/3) long. Every line is then
// equally likely anywhere in the sphere's volume, whatever the set.
void line_sample(int i, Pattern pattern, out vec2 s, out float column, out float per_length) {
    if (u_shift == 0) {
        s = pattern.rotation * vec2(u_samples[i].x * pattern.reflection, u_samples[i].y);
        column = u_samples[i].z;
        per_length = u_samples[i].w;
        return;
    }
    float v = fract(u_polar[i].z + pattern.shift.x);
    column = max(pow(1.0 - v, 1.0 / 3.0), 1e-2);
    float r = sqrt(max(1.0 - column * column, 0.0));
    s = pattern.rotation * (r * vec2(u_polar[i].x * pattern.reflection, u_polar[i].y));
    per_length = u_polar[i].w / column;
}
float open_fraction(vec3 p, vec3 n, float radius, Pattern pattern) {
    float open_sum = 0.0, available_sum = 0.0;
    for (int i = 0; i < VO_COUNT; ++i) {
        vec2 s;
        float column, per_length;
        line_sample(i, pattern, s, column, per_length);
        float open_len, available;
        line_lengths(p, n, radius, s, column, open_len, available);
        // Each line stands for its Voronoi region's volume: weight per unit of its length.
        open_sum += per_length * open_len;
        available_sum += per_length * available;
    }
    return line_result(open_sum / radius, available_sum / radius, 1.0);
}
#elif defined(VO_REFERENCE)
// VO_REFERENCE x VO_REFERENCE cells over the disk's square, one line through each centre
// inside the disk: every line stands for the same area, so its length is its volume.
float open_fraction(vec3 p, vec3 n, float radius, Pattern pattern) {
    float open_sum = 0.0, available_sum = 0.0, volume_sum = 0.0;
    for (int j = 0; j < VO_REFERENCE; ++j) {
        for (int i = 0; i < VO_REFERENCE; ++i) {
            vec2 s = (vec2(i, j) + 0.5) * (2.0 / float(VO_REFERENCE)) - 1.0;
            if (dot(s, s) >= 1.0) continue;
            float column = sqrt(1.0 - dot(s, s));
            float open_len, available;
            line_lengths(p, n, radius, s, column, open_len, available);
            open_sum += open_len;
            available_sum += available;
            volume_sum += 2.0 * radius * column;
        }
    }
    return line_result(open_sum, available_sum, volume_sum);
}
#elif defined(VO_POINTS)
// Point i where the pattern puts it. Shifted, its volume's share r^3 and its height h = z / r
// move round their ranges and the turn carries its azimuth: uniform in all three is uniform in
// the ball, so every point is equally likely anywhere in it, whatever the set.
vec3 point_sample(int i, Pattern pattern) {
    if (u_shift == 0) {
        return vec3(pattern.rotation * u_samples[i].xy, u_samples[i].z * pattern.reflection);
    }
    float r = pow(fract(u_polar[i].z + pattern.shift.x), 1.0 / 3.0);
    float h = fract(0.5 * u_polar[i].w + 0.5 + pattern.shift.y) * 2.0 - 1.0;
    vec2 xy = sqrt(max(1.0 - h * h, 0.0)) * (pattern.rotation * u_polar[i].xy);
    return r * vec3(xy, h * pattern.reflection);
}
float open_fraction(vec3 p, vec3 n, float radius, Pattern pattern) {
    float open_sum = 0.0;
    // Points on the tangent plane of a flat surface stay open, also where a texel's depth
    // spans a long stretch of a surface seen at a grazing angle.
    float bias = 0.02 * radius + 0.004 * -p.z;
    for (int i = 0; i < VO_COUNT; ++i) {
        vec3 s = point_sample(i, pattern);
        if (u_normal_clamp != 0 && dot(s, n) < 0.0) s = -s;
        vec3 x = p + radius * s;
        float behind = -x.z - scene_distance(scene_texel(project(x)));
        bool occluded = behind > bias && (u_thickness <= 0.0 || behind < u_thickness);
        open_sum += occluded ? 0.0 : u_samples[i].w;
    }
    return u_normal_clamp != 0 ? open_sum : clamp(2.0 * open_sum, 0.0, 1.0);
}
#elif defined(VO_AREA)
// The box model: the depths under the sphere's disk, relative to its centre, spread evenly
// over [mean - h, mean + h] (h = sqrt(3 variance)), the same for every column of the sphere.
// A column z from the centre plane (half-length z) is open for clamp(d, -z, z) + z of its
// length when the scene lies d behind the centre; over the sphere, with r dr = -z dz, the open
// fraction is 1/2 + 3 / (2 R^3) E[G'(d)] where G'(d) = integral_0^R z clamp(d, -z, z) dz and
// G its antiderivative in d, so the mean over the box is a difference of G.
float box_g(float d, float radius) {
    float a = abs(d);
    float m = min(a, radius);
    float m3 = m * m * m;
    return a * m3 / 3.0 - 0.125 * m3 * m + 0.25 * d * d * (radius * radius - m * m);
}
float box_g_slope(float d, float radius) {
    float a = abs(d);
    float m = min(a, radius);
    return sign(d) * (m * m * m / 3.0 + 0.5 * a * (radius * radius - m * m));
}
float box_mean_slope(float mean, float h, float radius) {
    if (h < 1e-3 * radius) return box_g_slope(mean, radius);
    return (box_g(mean + h, radius) - box_g(mean - h, radius)) / (2.0 * h);
}
// With a thickness T what lies more than T behind the scene is open again:
// + 1/2 - 3 / (2 R^3) E[G'(d + T)].
float box_open(float mean, float variance, float radius) {
    float h = sqrt(3.0 * max(variance, 0.0));
    float scale = 1.5 / (radius * radius * radius);
    float open = 0.5 + scale * box_mean_slope(mean, h, radius);
    if (u_thickness > 0.0) open += 0.5 - scale * box_mean_slope(mean + u_thickness, h, radius);
    return open;
}
// The tangent plane's distance at a scene uv (far where its ray misses the plane).
float plane_distance(vec3 p, vec3 n, vec2 uv) {
    float along = dot(n, view_position(uv, 1.0));
    return along < -1e-6 ? min(dot(n, p) / along, VO_MOMENTS_FAR) : VO_MOMENTS_FAR;
}
// The scene's and the tangent plane's distance moments through the same footprint: a bilinear
// fetch of mip `level` at uv, and the plane over the four texels it blends (each texel's box by
// a 2 x 2 Gauss rule, exact for a quadratic), weighted as the fetch weighs them.
void level_moments(vec3 p, vec3 n, vec2 uv, float level, out vec2 scene, out vec2 plane) {
    scene = textureLod(u_moments, uv * u_moments_scale, level).rg;
    float texel = exp2(level);  // scene pixels per texel of this level
    vec2 position = uv * vec2(u_scene_size) / texel - 0.5;
    vec2 base = floor(position), f = position - base;
    const float kGauss = 0.5 - 0.5 / 1.7320508;  // a box's Gauss points at 0.21 and 0.79
    plane = vec2(0.0);
    for (int j = 0; j < 2; ++j) {
        for (int i = 0; i < 2; ++i) {
            float w = (i == 0 ? 1.0 - f.x : f.x) * (j == 0 ? 1.0 - f.y : f.y);
            vec2 corner = (base + vec2(i, j)) * texel;
            for (int k = 0; k < 4; ++k) {
                vec2 g = vec2(k & 1, k >> 1) * (1.0 - 2.0 * kGauss) + kGauss;
                float t = plane_distance(p, n, (corner + g * texel) / vec2(u_scene_size));
                plane += 0.25 * w * vec2(t, t * t);
            }
        }
    }
}
float level_open(vec3 p, vec3 n, vec2 uv, float level, float radius) {
    vec2 scene, plane;
    level_moments(p, n, uv, level, scene, plane);
    float open = box_open(scene.x + p.z, scene.y - scene.x * scene.x, radius);
    if (u_normal_clamp == 0) return clamp(2.0 * open, 0.0, 1.0);
    float plane_open = box_open(plane.x + p.z, plane.y - plane.x * plane.x, radius);
    return plane_open > 1e-3 ? clamp(open / plane_open, 0.0, 1.0) : 1.0;
}
// One area sample: the moments at the mip level whose footprint spreads like the sphere's disk
// on the screen (a disk of radius r has per-axis variance r^2 / 4, as a bilinear footprint r
// texels wide), blended between the two nearest levels. Without the clamp, a flat surface
// fills half the sphere, so the open share is doubled. With it, the part of the sphere the
// scene fills above the tangent plane is what it fills beyond the plane's own share over the
// same footprint (f_plane - f_scene of f_plane), so a flat surface, tilted or not, is fully
// open and a wall beside it darkens it by what it adds.
float open_fraction(vec3 p, vec3 n, float radius, Pattern pattern) {
    float radius_texels = radius * u_projection.x / -p.z * 0.5 * float(u_scene_size.x);
    float lod = clamp(log2(radius_texels), 0.0, float(VO_MOMENTS_LEVELS - 1));
    float level = floor(lod);
    vec2 uv = project(p);
    float open = level_open(p, n, uv, level, radius);
    if (lod > level) open = mix(open, level_open(p, n, uv, level + 1.0, radius), lod - level);
    return open;
}
#endif

// A 4x4 ordered (Bayer) pattern of 16 rotations, every other one reflected. The rotations
// spread over the sample set's own symmetry period (2 pi / k for a set that k-fold rotation
// maps onto itself), or a symmetric set would repeat itself: the 9 electrostatic lines (a ring
// of 8 and the centre) turned in steps of 22.5 degrees take only 2 distinct positions. The
// shifts make the 16 cells a Hammersley set with the turn: cell k's shift is k's 4 bits
// reversed (and, for a point's height, k's base-3 digits reversed), so every quarter of the
// turn's range meets every quarter of the shift's.
uniform float u_rotation_span;
const int kBayer[16] = int[16](0, 8, 2, 10, 12, 4, 14, 6, 3, 11, 1, 9, 15, 7, 13, 5);
// Cell k's shifts, in 16ths and 27ths: k's 4 bits reversed, k's base-3 digits reversed.
const vec2 kShift[16] = vec2[16](vec2(0, 0), vec2(8, 9), vec2(4, 18), vec2(12, 3),
                                 vec2(2, 12), vec2(10, 21), vec2(6, 6), vec2(14, 15),
                                 vec2(1, 24), vec2(9, 1), vec2(5, 10), vec2(13, 19),
                                 vec2(3, 4), vec2(11, 13), vec2(7, 22), vec2(15, 7));
Pattern pixel_pattern(ivec2 pixel) {
    Pattern pattern;
#ifdef VO_REFERENCE
    pattern.rotation = mat2(1.0);  // the reference is not randomised
    pattern.reflection = 1.0;
    pattern.shift = vec2(0.0);
#else
    ivec2 q = pixel & 3;
    int bayer = kBayer[q.y * 4 + q.x];
    float angle = (float(bayer) + 0.5) * (u_rotation_span / 16.0);
    float c = cos(angle), s = sin(angle);
    pattern.rotation = mat2(c, s, -s, c);
    pattern.reflection = (bayer & 1) == 0 ? 1.0 : -1.0;
    pattern.shift = kShift[bayer] / vec2(16.0, 27.0);
#endif
    return pattern;
}

// The result with what the blur needs of the texel, so that it reads one texture per tap:
// (open, distance, view-space normal x and y); distance 0 where nothing receives obscurance.
vec4 pass_result(ivec2 pixel) {
    vec2 uv = (vec2(pixel) + 0.5) / vec2(u_target_size);
    ivec2 texel = scene_texel(uv);
    vec4 normal = scene_normal(texel);
    if (!receives(normal)) return vec4(1.0, 0.0, 0.0, 0.0);
    float distance = scene_distance(texel);
    vec3 n = normalize(normal.xyz);
    vec4 result = vec4(1.0, distance, n.xy);
    // A sphere smaller than a pixel has nothing the depth buffer can resolve.
    float radius_pixels = u_radii.x * u_projection.x / distance * 0.5 * float(u_scene_size.x);
    if (radius_pixels < 1.0) return result;
    vec3 p = view_position(uv, distance);
    Pattern pattern = pixel_pattern(pixel);
    float open = open_fraction(p, n, u_radii.x, pattern);
    if (u_radii.y > 0.0) {
        float second = open_fraction(p, n, u_radii.y, pattern);
        open = u_dual_minimum != 0 ? min(open, second) : open * second;
    }
    result.x = open;
    return result;
}
)";

const char* const kMomentsFragment = R"(
in vec2 v_uv;
uniform vec2 u_moments_scale;
layout(location = 0) out vec2 o_moments;
void main() {
    // The padding beyond the scene repeats its edge texels.
    float t = min(scene_distance(scene_texel(v_uv / u_moments_scale)), VO_MOMENTS_FAR);
    o_moments = vec2(t, t * t);
}
)";

const char* const kBlur = R"(
uniform sampler2D u_open;  // (open, distance, normal x, normal y), as the estimate wrote it
uniform ivec2 u_step;      // (1, 0) or (0, 1)
// Taps -2..2 weighted 1/2, 1, 1, 1, 1/2: every phase of the estimate's 4-pixel rotation
// pattern counts alike (the two ends share one), so the pattern cancels, with 5 fetches.
const float kTap[3] = float[3](1.0, 1.0, 0.5);
vec3 unpack_normal(vec2 xy) { return vec3(xy, sqrt(max(1.0 - dot(xy, xy), 0.0))); }
vec4 pass_result(ivec2 pixel) {
    ivec2 size = textureSize(u_open, 0);
    ivec2 centre = clamp(pixel, ivec2(0), size - 1);
    vec4 c = texelFetch(u_open, centre, 0);
    if (c.y <= 0.0) return c;  // nothing here receives obscurance
    vec3 n0 = unpack_normal(c.zw);
    float sum = 0.0, weights = 0.0;
    for (int k = -2; k <= 2; ++k) {
        vec4 q = texelFetch(u_open, clamp(centre + k * u_step, ivec2(0), size - 1), 0);
        float depth_weight = max(0.0, 1.0 - abs(q.y - c.y) / (0.03 * c.y));
        float normal_weight = pow(max(dot(unpack_normal(q.zw), n0), 0.0), 8.0);
        float w = kTap[abs(k)] * depth_weight * normal_weight * step(1e-6, q.y);
        sum += w * q.x;
        weights += w;
    }
    if (weights > 1e-5) c.x = sum / weights;
    return c;
}
)";

const char* const kFragmentHeader = "#version 330 core\n";
const char* const kComputeHeader = "#version 430 core\n";

const char* const kFragmentMain = R"(
layout(location = 0) out vec4 o_result;
void main() { o_result = pass_result(ivec2(gl_FragCoord.xy)); }
)";

const char* const kComputeMain = R"(
layout(local_size_x = VO_GROUP, local_size_y = VO_GROUP) in;
layout(rgba16f, binding = 0) writeonly uniform image2D u_target;
void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, imageSize(u_target)))) return;
    imageStore(u_target, pixel, pass_result(pixel));
}
)";

const char* const kCompositeFragment = R"(
in vec2 v_uv;
uniform sampler2D u_open;
uniform sampler2D u_colour;  // the scene's, with u_copy
uniform float u_strength;
uniform int u_show;
uniform int u_copy;  // write colour * obscurance (else obscurance, for multiplicative blending)
layout(location = 0) out vec4 o_color;
// The result at a scene texel: its own at full resolution; at half resolution the four nearest
// texels' bilinear mix, each weighted down by how far its distance is from the texel's (as the
// blur weighs taps), so no value crosses a silhouette; plain bilinear where none is near.
float open_at(ivec2 texel) {
    ivec2 size = textureSize(u_open, 0);
    if (size == u_scene_size) return texelFetch(u_open, texel, 0).r;
    float distance = scene_distance(texel);
    vec2 at = (vec2(texel) + 0.5) * vec2(size) / vec2(u_scene_size) - 0.5;
    ivec2 base = ivec2(floor(at));
    vec2 f = at - vec2(base);
    float sum = 0.0, weights = 0.0;
    for (int k = 0; k < 4; ++k) {
        ivec2 corner = ivec2(k & 1, k >> 1);
        vec4 t = texelFetch(u_open, clamp(base + corner, ivec2(0), size - 1), 0);
        vec2 along = mix(1.0 - f, f, vec2(corner));
        float depth_weight = max(0.0, 1.0 - abs(t.y - distance) / (0.03 * distance));
        float w = along.x * along.y * (depth_weight + 1e-4);
        sum += w * t.x;
        weights += w;
    }
    return sum / max(weights, 1e-8);
}
void main() {
    ivec2 texel = scene_texel(v_uv);
    float open = open_at(texel);
    float share = u_show != 0 ? 1.0 : scene_normal(texel).a;
    vec3 factor = vec3(mix(1.0, open, u_strength * share));
    if (u_copy != 0 && u_show == 0)
        o_color = vec4(texelFetch(u_colour, texel, 0).rgb * factor, 1.0);
    else
        o_color = vec4(factor, 1.0);
}
)";

}  // namespace nq::npr::obscurance

#include "technical/planar_shadow.h"

#include <cmath>
#include <cstddef>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/trigonometric.hpp>

namespace nq::npr::technical {
namespace {

constexpr float kTiny = 1e-6f;

bool engine_has_trace(const nqr_engine& engine) {
    return engine.size >= offsetof(nqr_engine, trace) + sizeof(engine.trace) &&
           engine.trace != nullptr;
}

// A unit vector along the plane: the light's own direction along it when it has one, else the
// world X (or Y) axis flattened onto the plane, so an overhead light still gets a sideways axis.
glm::vec3 along_plane(const glm::vec3& n, const glm::vec3& light) {
    const glm::vec3 candidates[] = {light, glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)};
    for (const glm::vec3& candidate : candidates) {
        const glm::vec3 flat = candidate - glm::dot(candidate, n) * n;
        const float length = glm::length(flat);
        if (length > 1e-4f) return flat / length;
    }
    return glm::vec3(1, 0, 0);
}

// Uniform scaling about a point of the plane keeps points of the plane on it.
glm::mat4 scale_about(const glm::vec3& point, float scale) {
    glm::mat4 m = glm::translate(glm::mat4(1.0f), point);
    m = glm::scale(m, glm::vec3(scale));
    return glm::translate(m, -point);
}

}  // namespace

ShadowPlane find_shadow_plane(const nqr_engine& engine, const glm::vec3& origin, float max_drop) {
    ShadowPlane plane;
    if (!engine_has_trace(engine) || !(max_drop > 0.0f)) return plane;
    const glm::vec3 end = origin - glm::vec3(0.0f, 0.0f, max_drop);
    nqr_trace trace{};
    trace.size = sizeof(nqr_trace);
    trace.fraction = 1.0f;
    engine.trace(engine.context, glm::value_ptr(origin), glm::value_ptr(end), &trace);
    if (trace.start_solid || !(trace.fraction < 1.0f)) return plane;
    const glm::vec3 normal = glm::make_vec3(trace.plane_normal);
    const float length = glm::length(normal);
    if (!(length > kTiny)) return plane;
    plane.found = true;
    plane.normal = normal / length;
    plane.distance = trace.plane_dist / length;
    plane.hit = glm::make_vec3(trace.end);
    return plane;
}

glm::mat4 planar_projection(const glm::vec3& n, float d, const glm::vec3& l) {
    // x' = x - (dot(n, x) - d) / dot(n, l) * l, written as a matrix (column-major: m[col][row]).
    const float n_dot_l = glm::dot(n, l);
    glm::mat4 m(1.0f);
    for (int col = 0; col < 3; ++col) {
        for (int row = 0; row < 3; ++row) m[col][row] -= l[row] * n[col] / n_dot_l;
    }
    for (int row = 0; row < 3; ++row) m[3][row] = l[row] * d / n_dot_l;
    return m;
}

glm::vec3 steepen_light(const glm::vec3& n, const glm::vec3& light_dir,
                        float min_elevation_degrees) {
    const float min_sine = std::sin(glm::radians(min_elevation_degrees));
    if (glm::dot(n, light_dir) >= min_sine) return light_dir;
    const glm::vec3 along = along_plane(n, light_dir);
    return min_sine * n + std::sqrt(1.0f - min_sine * min_sine) * along;
}

ShadowPasses build_shadow_passes(const ShadowPlane& plane, const glm::vec3& light_dir,
                                 const glm::vec3& centre, const ShadowSettings& settings,
                                 float caster_radius) {
    ShadowPasses passes;
    const float light_length = glm::length(light_dir);
    if (!settings.enabled || !plane.found || !(light_length > kTiny)) return passes;
    const glm::vec3 n = plane.normal;
    glm::vec3 light = light_dir / light_length;
    if (!(glm::dot(n, light) > kTiny)) return passes;  // at or below the plane
    light = steepen_light(n, light, kMinShadowLightElevationDegrees);
    passes.light = light;

    const glm::mat4 projection = planar_projection(n, plane.distance, light);
    const glm::vec3 shadow_centre = glm::vec3(projection * glm::vec4(centre, 1.0f));
    // A sphere's shadow is an ellipse with semi-axes r and r / dot(n, l).
    passes.bounds_centre = shadow_centre;
    passes.bounds_radius = caster_radius / glm::dot(n, light);
    if (!settings.penumbra) {
        passes.count = 1;
        passes.pass[0] = {projection, settings.alpha};
        return passes;
    }
    passes.bounds_radius += std::abs(settings.penumbra_offset);
    const glm::vec3 sideways = glm::cross(n, along_plane(n, light));
    const glm::vec3 offset = settings.penumbra_offset * sideways;
    passes.count = 3;
    passes.pass[0] = {scale_about(shadow_centre, settings.umbra_scale) * projection,
                      settings.alpha};
    passes.pass[1] = {glm::translate(glm::mat4(1.0f), offset) * projection,
                      settings.penumbra_alpha};
    passes.pass[2] = {glm::translate(glm::mat4(1.0f), -offset) * projection,
                      settings.penumbra_alpha};
    return passes;
}

}  // namespace nq::npr::technical

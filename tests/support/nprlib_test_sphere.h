// A synthetic alias-model sphere for shading tests: poles on the X axis, Quake's clockwise
// winding seen from outside, every vertex at one skin texel.
#pragma once

#include <cmath>
#include <numbers>
#include <optional>

#include "support/nprlib_test_support.h"

namespace nq::npr::test {

inline constexpr float kSphereRadius = 30.0f;

// Adds triangle (a, b, c) of pose 0 wound clockwise seen from outside (Quake's order), outside
// being away from `inside`.
inline void add_outward_triangle(AliasBuilder& b, glm::vec3 inside, int i0, int i1, int i2) {
    auto position = [&](int i) {
        const auto& v = b.poses[0][i];
        return glm::vec3(v[0], v[1], v[2]) * b.scale + b.origin;
    };
    const glm::vec3 p0 = position(i0), p1 = position(i1), p2 = position(i2);
    const glm::vec3 counter_clockwise_normal = glm::cross(p1 - p0, p2 - p0);
    const bool outward = glm::dot(counter_clockwise_normal, (p0 + p1 + p2) / 3.0f - inside) > 0;
    if (outward) {
        b.triangles.push_back({1, i0, i2, i1});
    } else {
        b.triangles.push_back({1, i0, i1, i2});
    }
}

inline int add_vertex(AliasBuilder& b, glm::vec3 model_position, glm::ivec2 st) {
    if (b.poses.empty()) b.poses.emplace_back();
    const glm::ivec3 packed = glm::ivec3(glm::round((model_position - b.origin) / b.scale));
    b.poses[0].push_back({static_cast<uint8_t>(packed.x), static_cast<uint8_t>(packed.y),
                          static_cast<uint8_t>(packed.z)});
    b.st.push_back({0, st.x, st.y});
    return static_cast<int>(b.poses[0].size() - 1);
}

// A sphere of kSphereRadius around the model origin with its poles on the X axis (the -X pole
// faces a camera on -X), every vertex at skin texel `st`.
inline void make_sphere(AliasBuilder& b, glm::ivec2 st, int stacks = 16, int slices = 24) {
    b.scale = glm::vec3(0.25f);
    b.origin = glm::vec3(-32.0f);
    const float pi = std::numbers::pi_v<float>;
    const int near_pole = add_vertex(b, {-kSphereRadius, 0, 0}, st);
    for (int i = 1; i < stacks; ++i) {
        const float theta = pi * i / stacks;
        for (int j = 0; j < slices; ++j) {
            const float phi = 2.0f * pi * j / slices;
            const float ring = kSphereRadius * std::sin(theta);
            add_vertex(
                b, {-kSphereRadius * std::cos(theta), ring * std::cos(phi), ring * std::sin(phi)},
                st);
        }
    }
    const int far_pole = add_vertex(b, {kSphereRadius, 0, 0}, st);
    auto ring_vertex = [&](int i, int j) { return 1 + (i - 1) * slices + j % slices; };
    const glm::vec3 centre(0.0f);
    for (int j = 0; j < slices; ++j) {
        add_outward_triangle(b, centre, near_pole, ring_vertex(1, j), ring_vertex(1, j + 1));
        add_outward_triangle(b, centre, far_pole, ring_vertex(stacks - 1, j),
                             ring_vertex(stacks - 1, j + 1));
        for (int i = 1; i + 1 < stacks; ++i) {
            add_outward_triangle(b, centre, ring_vertex(i, j), ring_vertex(i + 1, j),
                                 ring_vertex(i + 1, j + 1));
            add_outward_triangle(b, centre, ring_vertex(i, j), ring_vertex(i + 1, j + 1),
                                 ring_vertex(i, j + 1));
        }
    }
}

// The sphere's outward normal seen at the centre of window pixel (x, y) by a camera at `eye` on
// the -X axis looking along +X with a 90 degree field of view (front_camera() of the tests);
// nothing where the pixel's ray misses the sphere.
inline std::optional<glm::vec3> sphere_normal_at_pixel(int x, int y, glm::vec3 eye) {
    const float ndc_x = (x + 0.5f) / (kSize / 2.0f) - 1.0f;
    const float ndc_y = (y + 0.5f) / (kSize / 2.0f) - 1.0f;
    const glm::vec3 ray = glm::normalize(glm::vec3(1.0f, -ndc_x, ndc_y));
    const float b = glm::dot(eye, ray);
    const float disc = b * b - (glm::dot(eye, eye) - kSphereRadius * kSphereRadius);
    if (disc < 0.0f) return std::nullopt;
    return glm::normalize(eye + ray * (-b - std::sqrt(disc)));
}

}  // namespace nq::npr::test

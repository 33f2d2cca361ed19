#include "app/frame/showroom_meshes.h"

#include <cmath>
#include <numbers>

namespace nq::showroom {

namespace {

using Vec = std::array<float, 3>;

void quad(Mesh& m, int a, int b, int c, int d) {  // counter-clockwise seen from outside
    m.triangles.push_back({a, b, c});
    m.triangles.push_back({a, c, d});
}

}  // namespace

Mesh make_cube(float size) {
    float h = size / 2;
    Mesh m{"cube", {}, {}};
    for (int i = 0; i < 8; ++i) {
        m.positions.push_back({(i & 1) ? h : -h, (i & 2) ? h : -h, (i & 4) ? h : -h});
    }
    quad(m, 0, 2, 3, 1);  // -Z
    quad(m, 4, 5, 7, 6);  // +Z
    quad(m, 0, 1, 5, 4);  // -Y
    quad(m, 2, 6, 7, 3);  // +Y
    quad(m, 0, 4, 6, 2);  // -X
    quad(m, 1, 3, 7, 5);  // +X
    return m;
}

Mesh make_step(float size) {
    // Profile in the X-Z plane (counter-clockwise seen from -Y), extruded along Y.
    const float s = size, h = size / 2;
    const std::array<std::array<float, 2>, 6> profile = {
        {{-h, -h}, {h, -h}, {h, 0}, {0, 0}, {0, h}, {-h, h}}};
    Mesh m{"step", {}, {}};
    for (int side = 0; side < 2; ++side) {
        float y = side == 0 ? -s / 2 : s / 2;
        for (const auto& p : profile) m.positions.push_back({p[0], y, p[1]});
    }
    // The -Y cap (profile as listed is counter-clockwise seen from -Y): fan split into convex
    // parts.
    m.triangles.push_back({0, 1, 2});
    m.triangles.push_back({0, 2, 3});
    m.triangles.push_back({0, 3, 4});
    m.triangles.push_back({0, 4, 5});
    // The +Y cap: reversed.
    m.triangles.push_back({6, 8, 7});
    m.triangles.push_back({6, 9, 8});
    m.triangles.push_back({6, 10, 9});
    m.triangles.push_back({6, 11, 10});
    // Sides: each profile edge i -> i+1 becomes a quad.
    for (int i = 0; i < 6; ++i) {
        int j = (i + 1) % 6;
        quad(m, i, i + 6, j + 6, j);
    }
    return m;
}

Mesh make_sphere(float radius, int rings, int segments) {
    Mesh m{"sphere", {}, {}};
    m.positions.push_back({0, 0, -radius});
    for (int r = 1; r < rings; ++r) {
        float phi = std::numbers::pi_v<float> * r / rings - std::numbers::pi_v<float> / 2;
        for (int s = 0; s < segments; ++s) {
            float theta = 2 * std::numbers::pi_v<float> * s / segments;
            m.positions.push_back({radius * std::cos(phi) * std::cos(theta),
                                   radius * std::cos(phi) * std::sin(theta),
                                   radius * std::sin(phi)});
        }
    }
    int top = static_cast<int>(m.positions.size());
    m.positions.push_back({0, 0, radius});
    auto at = [&](int ring, int s) { return 1 + (ring - 1) * segments + (s % segments); };
    for (int s = 0; s < segments; ++s) m.triangles.push_back({0, at(1, s + 1), at(1, s)});
    for (int r = 1; r < rings - 1; ++r) {
        for (int s = 0; s < segments; ++s)
            quad(m, at(r, s), at(r, s + 1), at(r + 1, s + 1), at(r + 1, s));
    }
    for (int s = 0; s < segments; ++s)
        m.triangles.push_back({top, at(rings - 1, s), at(rings - 1, s + 1)});
    return m;
}

Mesh make_torus(float major, float minor, int rings, int segments) {
    Mesh m{"torus", {}, {}};
    for (int r = 0; r < rings; ++r) {
        float u = 2 * std::numbers::pi_v<float> * r / rings;
        for (int s = 0; s < segments; ++s) {
            float v = 2 * std::numbers::pi_v<float> * s / segments;
            float d = major + minor * std::cos(v);
            m.positions.push_back({d * std::cos(u), d * std::sin(u), minor * std::sin(v)});
        }
    }
    auto at = [&](int r, int s) { return (r % rings) * segments + (s % segments); };
    for (int r = 0; r < rings; ++r) {
        for (int s = 0; s < segments; ++s)
            quad(m, at(r, s), at(r + 1, s), at(r + 1, s + 1), at(r, s + 1));
    }
    return m;
}

}  // namespace nq::showroom

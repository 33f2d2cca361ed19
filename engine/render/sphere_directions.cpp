#include "render/sphere_directions.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>

namespace nq {

namespace {

using Triangle = std::array<int, 3>;

// The 12 vertices (0, +-1, +-phi) and their cyclic permutations, and 20 faces.
void icosahedron(std::vector<glm::vec3>& vertices, std::vector<Triangle>& triangles) {
    const float phi = (1.0f + std::sqrt(5.0f)) / 2.0f;
    vertices = {{-1, phi, 0}, {1, phi, 0}, {-1, -phi, 0}, {1, -phi, 0},
                {0, -1, phi}, {0, 1, phi}, {0, -1, -phi}, {0, 1, -phi},
                {phi, 0, -1}, {phi, 0, 1}, {-phi, 0, -1}, {-phi, 0, 1}};
    for (glm::vec3& v : vertices) v = glm::normalize(v);
    triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                 {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                 {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                 {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
}

// The vertex halfway along edge (a, b) on the sphere, added once per edge.
int midpoint(int a, int b, std::vector<glm::vec3>& vertices,
             std::map<std::pair<int, int>, int>& made) {
    const std::pair<int, int> key(std::min(a, b), std::max(a, b));
    if (const auto it = made.find(key); it != made.end()) return it->second;
    vertices.push_back(glm::normalize(vertices[a] + vertices[b]));
    const int index = int(vertices.size()) - 1;
    made.emplace(key, index);
    return index;
}

void subdivide(std::vector<glm::vec3>& vertices, std::vector<Triangle>& triangles) {
    std::map<std::pair<int, int>, int> made;
    std::vector<Triangle> finer;
    finer.reserve(triangles.size() * 4);
    for (const Triangle& t : triangles) {
        const int ab = midpoint(t[0], t[1], vertices, made);
        const int bc = midpoint(t[1], t[2], vertices, made);
        const int ca = midpoint(t[2], t[0], vertices, made);
        finer.push_back({t[0], ab, ca});
        finer.push_back({t[1], bc, ab});
        finer.push_back({t[2], ca, bc});
        finer.push_back({ab, bc, ca});
    }
    triangles = std::move(finer);
}

}  // namespace

int sphere_direction_count(int level) {
    level = std::clamp(level, 0, kMaxSphereLevel);
    return 10 * (1 << (2 * level)) + 2;
}

std::vector<glm::vec3> sphere_directions(int level) {
    std::vector<glm::vec3> vertices;
    std::vector<Triangle> triangles;
    icosahedron(vertices, triangles);
    for (int i = 0; i < std::clamp(level, 0, kMaxSphereLevel); ++i) subdivide(vertices, triangles);
    return vertices;
}

}  // namespace nq

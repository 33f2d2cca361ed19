// Valve's ambient cube: the light arriving at a point from six directions, one RGB value per
// face of a cube: +X, -X, +Y, -Y, +Z, -Z (world axes, the order of
// nqr_entity_light.ambient_cube). Shading a normal n mixes the faces by n's squared components
// (Valve: n.x^2 * (n.x > 0 ? +X : -X) + ...).
#pragma once

#include <array>

#include <glm/glm.hpp>

namespace nq {

inline constexpr int kCubeFaces = 6;

inline constexpr std::array<glm::vec3, kCubeFaces> kCubeAxes = {
    glm::vec3(1, 0, 0),  glm::vec3(-1, 0, 0), glm::vec3(0, 1, 0),
    glm::vec3(0, -1, 0), glm::vec3(0, 0, 1),  glm::vec3(0, 0, -1)};

struct AmbientCube {
    std::array<glm::vec3, kCubeFaces> faces{};  // RGB, Quake light units (128 = normal)
};

}  // namespace nq

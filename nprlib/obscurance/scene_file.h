// One frame's geometry for the ray-traced obscurance reference (tool vo_reference): the
// camera's projection and viewport, and every triangle in view space, flagged solid (it blocks
// the sphere around a point) or not (sky and liquids: they hide what lies behind them from the
// camera, but the obscurance passes through them, as the pass leaves them out).
//
// The file ("vo_dump_scene" writes it) is little-endian: "NQVOSCN1", u32 width, u32 height,
// f32 projection[16] (column-major, view to clip), u32 triangle count, then per triangle
// f32 a[3], b[3], c[3] and u32 flags (bit 0: solid). Untrusted input: parse_scene checks every
// size and value and says where a file goes wrong.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace nq::npr::obscurance {

struct SceneTriangle {
    glm::vec3 a{0.0f}, b{0.0f}, c{0.0f};
    bool solid = true;
};

struct ObscuranceScene {
    uint32_t width = 0, height = 0;
    float projection[16] = {};
    std::vector<SceneTriangle> triangles;
};

inline constexpr uint32_t kMaxSceneSide = 16384;

std::vector<uint8_t> encode_scene(const ObscuranceScene& scene);

struct SceneParse {
    std::optional<ObscuranceScene> scene;
    std::string error;  // "<file>: offset N: problem" when scene is empty
};
SceneParse parse_scene(std::span<const uint8_t> bytes, const std::string& file);

}  // namespace nq::npr::obscurance

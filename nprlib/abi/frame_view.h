// What every style's drawers read from a frame's camera, as glm values: the matrices, the eye
// and its axes, the view frustum's side planes.
#pragma once

#include <array>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "nqr_renderer.h"

namespace nq::npr {

struct FrameView {
    glm::mat4 view_projection{1.0f};
    glm::mat4 view{1.0f};
    glm::vec3 eye{0.0f}, forward{1, 0, 0}, right{0, -1, 0}, up{0, 0, 1};
    // The frustum's side planes (n, d) as the engine hands them (none in a default view).
    std::array<glm::vec4, 4> side_planes{};
    int num_side_planes = 0;
};

// False when the frame (or its camera) is older than the ABI prefix this nprlib reads.
bool read_frame_view(const nqr_frame* frame, FrameView& out);

glm::mat4 mat4_from(const float* column_major);

// True when the sphere lies wholly outside one side plane of the view (never without planes).
bool sphere_outside_view(const FrameView& view, const glm::vec3& centre, float radius);

// Normals from model space to view space.
glm::mat3 normal_to_view(const FrameView& view, const glm::mat4& model);

}  // namespace nq::npr

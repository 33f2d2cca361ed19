#include "abi/frame_view.h"

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "abi/abi_access.h"

namespace nq::npr {

glm::mat4 mat4_from(const float* column_major) {
    return glm::make_mat4(column_major);
}

bool read_frame_view(const nqr_frame* frame, FrameView& out) {
    if (!frame_readable(frame)) return false;
    const nqr_camera& camera = *frame->camera;
    out.view_projection = mat4_from(camera.view_projection);
    out.view = mat4_from(camera.view);
    out.eye = glm::make_vec3(camera.origin);
    out.forward = glm::make_vec3(camera.forward);
    out.right = glm::make_vec3(camera.right);
    out.up = glm::make_vec3(camera.up);
    out.num_side_planes = 0;
    for (const float* plane : frame->view_planes) {
        out.side_planes[out.num_side_planes++] = glm::make_vec4(plane);
    }
    return true;
}

bool sphere_outside_view(const FrameView& view, const glm::vec3& centre, float radius) {
    for (int i = 0; i < view.num_side_planes; ++i) {
        const glm::vec4& plane = view.side_planes[i];
        if (glm::dot(glm::vec3(plane), centre) - plane.w < -radius) return true;
    }
    return false;
}

glm::mat3 normal_to_view(const FrameView& view, const glm::mat4& model) {
    return glm::inverseTranspose(glm::mat3(view.view * model));
}

}  // namespace nq::npr

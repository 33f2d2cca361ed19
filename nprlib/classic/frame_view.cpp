#include "classic/frame_view.h"

#include <epoxy/gl.h>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "classic/abi_access.h"

namespace nq::npr::classic {

glm::mat4 mat4_from(const float* column_major) {
    return glm::make_mat4(column_major);
}

bool read_frame_view(const nqr_frame* frame, FrameView& out) {
    if (!frame_readable(frame) || !has_known_prefix(&frame->camera)) return false;
    const nqr_camera& camera = frame->camera;
    out.view_projection = mat4_from(camera.view_projection);
    out.view = mat4_from(camera.view);
    out.eye = glm::make_vec3(camera.origin);
    out.forward = glm::make_vec3(camera.forward);
    out.right = glm::make_vec3(camera.right);
    out.up = glm::make_vec3(camera.up);
    out.num_side_planes = 0;
    if (frame_has_view_planes(*frame)) {
        for (const float* plane : frame->view_planes) {
            out.side_planes[out.num_side_planes++] = glm::make_vec4(plane);
        }
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

void begin_classic_pass() {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_TRUE);
    glDepthRange(0.0, 1.0);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
}

void end_classic_pass() {
    glDepthMask(GL_TRUE);
    glDepthRange(0.0, 1.0);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glBindVertexArray(0);
    glUseProgram(0);
    glActiveTexture(GL_TEXTURE0);
}

float entity_alpha(float alpha) {
    return (alpha <= 0.0f || alpha >= 1.0f) ? 1.0f : alpha;
}

AliasPass alias_pass_of(const nqr_entity& entity) {
    if ((entity.flags & NQR_ENTITY_VIEWMODEL) != 0) return AliasPass::view_model;
    return entity_alpha(entity.alpha) < 1.0f ? AliasPass::translucent : AliasPass::opaque;
}

}  // namespace nq::npr::classic

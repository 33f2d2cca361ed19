#include "technical/shadow_drawer.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <iterator>

#include <glm/gtc/type_ptr.hpp>

#include "classic/alias_pose_glsl.h"

namespace nq::npr::technical {
namespace {

// The pose library (alias_pose_glsl.h) goes between the header and the body.
constexpr char kVertexHeader[] = "#version 330 core\n";
constexpr char kVertexBody[] = R"(
layout(location = 0) in uint a_pose_vertex;
uniform mat4 u_model_to_clip;  // view_projection * world_to_plane * model
void main() {
    gl_Position = u_model_to_clip * vec4(pose_position(int(a_pose_vertex)), 1.0);
}
)";

constexpr char kFragment[] = R"(#version 330 core
uniform vec4 u_color;
layout(location = 0) out vec4 o_color;
void main() {
    o_color = u_color;
}
)";

constexpr int kUnitPoses = 0;
constexpr GLint kMaxStencilReference = 255;  // 8-bit stencil; 0 is the cleared value
// Shadow and floor share their depth; this pulls the shadow just in front (slope-aware).
constexpr float kOffsetFactor = -1.0f;
constexpr float kOffsetUnits = -2.0f;

void begin_shadow_state() {
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_FALSE);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(kOffsetFactor, kOffsetUnits);
    glEnable(GL_STENCIL_TEST);
    glStencilMask(0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glColorMaski(1, GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    // Only the triangles facing the light: on a closed model the ones facing away project
    // inside them, so the shadow is the same with half the triangles to set up. Projected
    // onto the floor along the light, light-facing triangles keep their winding as seen from
    // above (where the camera must be to see the floor): Quake's clockwise front.
    glEnable(GL_CULL_FACE);
    glFrontFace(GL_CW);
    glCullFace(GL_BACK);
}

void end_shadow_state() {
    glDisable(GL_CULL_FACE);
    glFrontFace(GL_CCW);
    glColorMaski(1, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDisable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 0, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(0.0f, 0.0f);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    glBindVertexArray(0);
    glUseProgram(0);
    glActiveTexture(GL_TEXTURE0);
}

}  // namespace

bool ShadowDrawer::init(gl::ObjectTracker* tracker, std::string& error) {
    const std::string vertex =
        std::string(kVertexHeader) + classic::kAliasPoseLibrary + kVertexBody;
    gl::ProgramBuild build =
        gl::Program::build({"technical shadow", vertex.c_str(), kFragment}, tracker);
    if (!build.ok()) {
        error = build.error;
        return false;
    }
    program_ = std::move(build.program);
    gl::bind_sampler_units(program_, {"u_poses"});
    next_reference_ = 0;
    return true;
}

void ShadowDrawer::reset() {
    program_.reset();
    next_reference_ = 0;
}

void ShadowDrawer::begin_frame() {
    next_reference_ = 0;
}

GLint ShadowDrawer::next_stencil_reference() {
    if (next_reference_ == 0 || next_reference_ > kMaxStencilReference) {
        glClearStencil(0);
        glClear(GL_STENCIL_BUFFER_BIT);
        next_reference_ = 1;
    }
    return next_reference_++;
}

void ShadowDrawer::draw_entity(const classic::FrameView& view, const nqr_entity& entity,
                               const classic::AliasModelGpu& model, const ShadowPasses& passes,
                               const ShadowSettings& settings) {
    if (!program_ || passes.count <= 0) return;
    program_.use();
    classic::set_alias_pose_uniforms(program_, model, entity, kUnitPoses);
    const glm::mat4 model_matrix = classic::mat4_from(entity.model_matrix);
    glBindVertexArray(model.vertex_array());
    begin_shadow_state();
    const int count = std::min(passes.count, static_cast<int>(std::size(passes.pass)));
    for (int i = 0; i < count; ++i) {
        const ShadowPass& pass = passes.pass[i];
        const glm::mat4 model_to_clip = view.view_projection * pass.world_to_plane * model_matrix;
        glUniformMatrix4fv(program_.location("u_model_to_clip"), 1, GL_FALSE,
                           glm::value_ptr(model_to_clip));
        glUniform4f(program_.location("u_color"), settings.color.r, settings.color.g,
                    settings.color.b, pass.alpha);
        glStencilFunc(GL_NOTEQUAL, next_stencil_reference(), 0xFF);
        glDrawElements(GL_TRIANGLES, model.index_count(), GL_UNSIGNED_INT, nullptr);
    }
    end_shadow_state();
}

}  // namespace nq::npr::technical

#include "classic/alias_drawer.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <string>

#include <glm/gtc/type_ptr.hpp>

#include "abi/abi_access.h"
#include "abi/frame_view.h"
#include "classic/alias_pose_glsl.h"
#include "classic/classic_pass.h"
#include "gl/texture_upload.h"

namespace nq::npr::classic {
namespace {

// The pose library (alias_pose_glsl.h) goes between the header and the body.
constexpr char kVertexHeader[] = "#version 330 core\n";
constexpr char kVertexBody[] = R"(
layout(location = 0) in uint a_pose_vertex;
layout(location = 1) in vec2 a_uv;
uniform mat4 u_model;
uniform mat4 u_view_projection;
uniform mat3 u_normal_to_view;
uniform vec3 u_light_direction;
uniform float u_ambient;
uniform float u_directional;
uniform vec3 u_light_color;
out vec2 v_uv;
out vec3 v_shade;
out vec3 v_normal;
void main() {
    vec3 normal = pose_normal(int(a_pose_vertex));
    vec4 world = u_model * vec4(pose_position(int(a_pose_vertex)), 1.0);
    gl_Position = u_view_projection * world;
    vec3 world_normal = mat3(u_model) * normal;
    float len = length(world_normal);
    world_normal = len > 1e-6 ? world_normal / len : vec3(0.0, 0.0, 1.0);
    float shade = u_ambient + u_directional * max(dot(world_normal, u_light_direction), 0.0);
    v_shade = shade * u_light_color;
    v_uv = a_uv;
    v_normal = u_normal_to_view * normal;
}
)";

constexpr char kFragment[] = R"(#version 330 core
in vec2 v_uv;
in vec3 v_shade;
in vec3 v_normal;
uniform sampler2D u_skin;
uniform sampler2D u_fullbright;
uniform float u_alpha;
uniform float u_alpha_cutoff;
layout(location = 0) out vec4 o_color;
layout(location = 1) out vec4 o_normal;
void main() {
    vec4 base = texture(u_skin, v_uv);
    if (base.a < u_alpha_cutoff) discard;
    vec3 color = base.rgb * v_shade + texture(u_fullbright, v_uv).rgb;
    o_color = vec4(color, u_alpha);
    vec3 n = length(v_normal) > 1e-6 ? normalize(v_normal) : vec3(0.0, 0.0, 1.0);
    o_normal = vec4(n * 0.5 + 0.5, 1.0);
}
)";

constexpr int kUnitSkin = 0;
constexpr int kUnitFullbright = 1;
constexpr int kUnitPoses = 2;
constexpr float kHoleyAlphaCutoff = 0.666f;

bool is_view_model(const nqr_entity& entity) {
    return (entity.flags & NQR_ENTITY_VIEWMODEL) != 0;
}

}  // namespace

bool AliasDrawer::init(gl::ObjectTracker* tracker, const uint8_t* palette_rgb, std::string& error) {
    const std::string vertex = std::string(kVertexHeader) + kAliasPoseLibrary + kVertexBody;
    gl::ProgramBuild build =
        gl::Program::build({"classic alias", vertex.c_str(), kFragment}, tracker);
    if (!build.ok()) {
        error = build.error;
        return false;
    }
    program_ = std::move(build.program);
    gl::bind_sampler_units(program_, {"u_skin", "u_fullbright", "u_poses"});
    black_ = gl::create_solid_texture(tracker, 0, 0, 0, 0);
    translated_.init(tracker, palette_rgb);
    return true;
}

void AliasDrawer::reset() {
    translated_.reset();
    program_.reset();
    black_.reset();
}

void AliasDrawer::set_lighting(const nqr_entity& entity) {
    float ambient = 1.0f, directional = 0.0f;
    glm::vec3 direction(0.0f, 0.0f, 1.0f), colour(1.0f);
    const nqr_entity_light& light = *entity.light;
    if (!(entity.flags & NQR_ENTITY_FULLBRIGHT) && light_readable(&light)) {
        ambient = light.ambient;
        directional = light.directional;
        direction = glm::make_vec3(light.direction);
        colour = glm::make_vec3(light.color);
        if (is_view_model(entity)) ambient = std::max(ambient, settings.view_model_min_ambient);
    }
    glUniform1f(program_.location("u_ambient"), ambient);
    glUniform1f(program_.location("u_directional"), directional);
    glUniform3fv(program_.location("u_light_direction"), 1, glm::value_ptr(direction));
    glUniform3fv(program_.location("u_light_color"), 1, glm::value_ptr(colour));
}

GLuint AliasDrawer::skin_texture(const nqr_frame& frame, const nqr_entity& entity,
                                 const AliasModelGpu& model, const SkinImageGpu& image) {
    if (entity.has_translation) {
        const GLuint translated =
            translated_.get(entity.model, model, entity.skin, entity.skin_image, entity.top_color,
                            entity.bottom_color, frame.number);
        if (translated != 0) return translated;
    }
    return image.base.id();
}

void AliasDrawer::draw_entity(const nqr_frame& frame, const FrameView& view,
                              const nqr_entity& entity, const AliasModelGpu& model) {
    const SkinImageGpu* image = model.skin_image(entity.skin, entity.skin_image);
    if (!image) return;
    program_.use();
    glUniformMatrix4fv(program_.location("u_view_projection"), 1, GL_FALSE,
                       glm::value_ptr(view.view_projection));
    set_alias_pose_uniforms(program_, model, entity, kUnitPoses);
    const glm::mat4 model_matrix = mat4_from(entity.model_matrix);
    glUniformMatrix4fv(program_.location("u_model"), 1, GL_FALSE, entity.model_matrix);
    const glm::mat3 normals = normal_to_view(view, model_matrix);
    glUniformMatrix3fv(program_.location("u_normal_to_view"), 1, GL_FALSE, glm::value_ptr(normals));
    set_lighting(entity);
    glUniform1f(program_.location("u_alpha"), entity_alpha(entity.alpha));
    glUniform1f(program_.location("u_alpha_cutoff"), model.holey() ? kHoleyAlphaCutoff : 0.0f);

    glActiveTexture(GL_TEXTURE0 + kUnitSkin);
    glBindTexture(GL_TEXTURE_2D, skin_texture(frame, entity, model, *image));
    glActiveTexture(GL_TEXTURE0 + kUnitFullbright);
    glBindTexture(GL_TEXTURE_2D, image->fullbright ? image->fullbright.id() : black_.id());
    glBindVertexArray(model.vertex_array());
    // Quake winds alias triangles clockwise seen from outside: cull the inside (as GLQuake did),
    // which also keeps a translucent model from blending its far side in.
    glEnable(GL_CULL_FACE);
    glFrontFace(GL_CW);
    glCullFace(GL_BACK);
    const bool translucent = entity_alpha(entity.alpha) < 1.0f;
    if (translucent) {
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glDepthMask(GL_FALSE);
    }
    glDrawElements(GL_TRIANGLES, model.index_count(), GL_UNSIGNED_INT, nullptr);
    if (translucent) {
        glDisable(GL_BLEND);
        glDepthMask(GL_TRUE);
    }
    glFrontFace(GL_CCW);
    glDisable(GL_CULL_FACE);
}

void AliasDrawer::draw_pass(const nqr_frame& frame, const FrameView& view,
                            const ModelRegistry& models, AliasPass pass) {
    for (uint32_t i = 0; i < frame.num_alias_entities; ++i) {
        const nqr_entity* entity = frame.alias_entities[i];
        if (!entity_in_view(entity) || alias_pass_of(*entity) != pass) continue;
        const RegisteredModel* model = models.find(entity->model);
        if (!model || !model->alias) continue;
        draw_entity(frame, view, *entity, *model->alias);
    }
}

void AliasDrawer::draw_alias_entities(const nqr_frame& frame, const ModelRegistry& models) {
    FrameView view;
    if (!read_frame_view(&frame, view) || !frame.alias_entities || !program_) return;
    begin_classic_pass();
    draw_pass(frame, view, models, AliasPass::opaque);
    draw_pass(frame, view, models, AliasPass::translucent);
    glDepthRange(0.0, settings.view_model_depth_max);
    draw_pass(frame, view, models, AliasPass::view_model);
    end_classic_pass();
}

}  // namespace nq::npr::classic

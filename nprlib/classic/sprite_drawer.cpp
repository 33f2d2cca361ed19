#include "classic/sprite_drawer.h"

#include <epoxy/gl.h>

#include <glm/gtc/type_ptr.hpp>

#include "abi/abi_access.h"
#include "abi/frame_view.h"
#include "classic/classic_pass.h"
#include "classic/sprite_orientation.h"

namespace nq::npr::classic {
namespace {

// Corners as a triangle strip: 0 left-down, 1 right-down, 2 left-up, 3 right-up. Texture t runs
// down the image (row 0 at the top), as the sprite's pixel rows do.
constexpr char kVertex[] = R"(#version 330 core
uniform mat4 u_view_projection;
uniform vec3 u_origin;
uniform vec3 u_right;
uniform vec3 u_up;
uniform vec4 u_rect;
out vec2 v_uv;
void main() {
    bool right_side = (gl_VertexID & 1) == 1;
    bool top = gl_VertexID >= 2;
    vec3 world = u_origin + u_right * (right_side ? u_rect.y : u_rect.x) +
                 u_up * (top ? u_rect.w : u_rect.z);
    v_uv = vec2(right_side ? 1.0 : 0.0, top ? 0.0 : 1.0);
    gl_Position = u_view_projection * vec4(world, 1.0);
}
)";

constexpr char kFragment[] = R"(#version 330 core
in vec2 v_uv;
uniform sampler2D u_texture;
uniform float u_alpha;
layout(location = 0) out vec4 o_color;
layout(location = 1) out vec4 o_normal;
void main() {
    vec4 texel = texture(u_texture, v_uv);
    if (texel.a < 0.666) discard;
    o_color = vec4(texel.rgb, u_alpha);
    o_normal = vec4(0.5, 0.5, 1.0, 1.0);
}
)";

}  // namespace

bool SpriteDrawer::init(gl::ObjectTracker* tracker, std::string& error) {
    gl::ProgramBuild build = gl::Program::build({"classic sprite", kVertex, kFragment}, tracker);
    if (!build.ok()) {
        error = build.error;
        return false;
    }
    program_ = std::move(build.program);
    gl::bind_sampler_units(program_, {"u_texture"});
    empty_vertex_array_ = gl::VertexArray::create(tracker);
    return true;
}

void SpriteDrawer::reset() {
    program_.reset();
    empty_vertex_array_.reset();
}

void SpriteDrawer::draw_entity(const FrameView& view, const nqr_entity& entity,
                               const SpriteModelGpu& model) {
    const SpriteImageGpu* image = model.image(entity.pose0);
    if (!image) return;
    const glm::vec3 origin = glm::make_vec3(entity.origin);
    const SpriteAxes axes = sprite_axes(model.type(), {view.eye, view.right, view.up}, origin,
                                        glm::make_vec3(entity.angles));
    const float scale = entity.scale > 0.0f ? entity.scale : 1.0f;
    program_.use();
    glUniformMatrix4fv(program_.location("u_view_projection"), 1, GL_FALSE,
                       glm::value_ptr(view.view_projection));
    glUniform3fv(program_.location("u_origin"), 1, glm::value_ptr(origin));
    glUniform3fv(program_.location("u_right"), 1, glm::value_ptr(axes.right * scale));
    glUniform3fv(program_.location("u_up"), 1, glm::value_ptr(axes.up * scale));
    // left, right, down, up in sprite units from the origin (origin_y is the top edge).
    glUniform4f(program_.location("u_rect"), image->origin_x, image->origin_x + image->width,
                image->origin_y - image->height, image->origin_y);
    const float alpha = entity_alpha(entity.alpha);
    glUniform1f(program_.location("u_alpha"), alpha);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, image->texture.id());
    glBindVertexArray(empty_vertex_array_.id());
    if (alpha < 1.0f) {
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glDepthMask(GL_FALSE);
    }
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    if (alpha < 1.0f) {
        glDisable(GL_BLEND);
        glDepthMask(GL_TRUE);
    }
}

void SpriteDrawer::draw_sprite_entities(const nqr_frame& frame, const ModelRegistry& models) {
    FrameView view;
    if (!read_frame_view(&frame, view) || !frame.sprite_entities || !program_) return;
    begin_classic_pass();
    for (uint32_t i = 0; i < frame.num_sprite_entities; ++i) {
        const nqr_entity* entity = frame.sprite_entities[i];
        if (!entity_in_view(entity)) continue;
        const RegisteredModel* model = models.find(entity->model);
        if (!model || !model->sprite) continue;
        draw_entity(view, *entity, *model->sprite);
    }
    end_classic_pass();
}

}  // namespace nq::npr::classic

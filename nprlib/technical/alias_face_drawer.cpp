#include "technical/alias_face_drawer.h"

#include <epoxy/gl.h>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "abi/abi_access.h"
#include "abi/frame_view.h"
#include "classic/alias_pass_state.h"
#include "classic/alias_pose_glsl.h"
#include "gl/texture_upload.h"
#include "technical/shading_glsl.h"

namespace nq::npr::technical {
namespace {

// The libraries (alias_pose_glsl.h, shading_glsl.h) go between the header and the body.
constexpr char kHeader[] = "#version 330 core\n";
constexpr char kVertexBody[] = R"(
layout(location = 0) in uint a_pose_vertex;
layout(location = 1) in vec2 a_uv;
uniform sampler2D u_skin;
uniform mat4 u_model;
uniform mat4 u_view_projection;
uniform mat3 u_normal_to_world;
uniform mat3 u_normal_to_view;
out vec2 v_uv;
out vec3 v_world_normal;
out vec3 v_view_normal;
out float v_height;
void main() {
    vec3 position = pose_position(int(a_pose_vertex));
    vec3 normal = pose_normal(int(a_pose_vertex));
    gl_Position = u_view_projection * (u_model * vec4(position, 1.0));
    v_uv = a_uv;
    v_world_normal = u_normal_to_world * normal;
    v_view_normal = u_normal_to_view * normal;
    v_height = position.z;
}
)";

constexpr char kFragmentBody[] = R"(
in vec2 v_uv;
in vec3 v_world_normal;
in vec3 v_view_normal;
in float v_height;
uniform sampler2D u_skin;
uniform vec3 u_kd_average;
uniform sampler2D u_fullbright;
uniform vec3 u_light_direction;
uniform float u_alpha;
uniform float u_alpha_cutoff;
layout(location = 0) out vec4 o_color;
layout(location = 1) out vec4 o_normal;
vec3 unit_or_up(vec3 v) {
    float len = length(v);
    return len > 1e-6 ? v / len : vec3(0.0, 0.0, 1.0);
}
void main() {
    vec4 texel = texture(u_skin, v_uv);
    if (texel.a < u_alpha_cutoff) discard;  // cutoff 0: never
    vec3 kd = surface_kd_from(u_kd_average, texel.rgb);
    vec3 shaded = technical_shade(kd, unit_or_up(v_world_normal), u_light_direction, v_height);
    o_color = vec4(shaded + texture(u_fullbright, v_uv).rgb, u_alpha);
    o_normal = vec4(unit_or_up(v_view_normal) * 0.5 + 0.5, 1.0);
}
)";

constexpr int kUnitSkin = 0;
constexpr int kUnitFullbright = 1;
constexpr int kUnitPoses = 2;
constexpr float kHoleyAlphaCutoff = 0.666f;  // as the classic drawer

}  // namespace

bool AliasFaceDrawer::init(gl::ObjectTracker* tracker, std::string& error) {
    reset();
    tracker_ = tracker;
    black_ = gl::create_solid_texture(tracker, 0, 0, 0, 0);
    // The default variant now, so that a broken shader shows at start-up.
    return build_variant(shading_variant(ShadingSettings{}), error) != nullptr;
}

gl::Program* AliasFaceDrawer::build_variant(int variant, std::string& error) {
    gl::Program& program = programs_[static_cast<size_t>(variant)];
    if (program) return &program;
    const std::string defines = shading_defines(variant);
    const std::string vertex =
        std::string(kHeader) + defines + classic::kAliasPoseLibrary + kShadingLibrary + kVertexBody;
    const std::string fragment = std::string(kHeader) + defines + kShadingLibrary + kFragmentBody;
    gl::ProgramBuild build =
        gl::Program::build({"technical alias faces", vertex.c_str(), fragment.c_str()}, tracker_);
    if (!build.ok()) {
        error = build.error;
        return nullptr;
    }
    program = std::move(build.program);
    gl::bind_sampler_units(program, {"u_skin", "u_fullbright", "u_poses"});
    return &program;
}

void AliasFaceDrawer::reset() {
    for (gl::Program& program : programs_) program.reset();
    program_ = nullptr;
    black_.reset();
}

void AliasFaceDrawer::set_light_direction(const nqr_entity& entity) {
    // An engine too old to sample light, or no dominant light: light from straight above.
    glm::vec3 direction(0.0f, 0.0f, 1.0f);
    if (npr::light_readable(entity.light)) {
        const glm::vec3 sampled = glm::make_vec3(entity.light->direction);
        const float length = glm::length(sampled);
        if (length > 1e-6f) direction = sampled / length;
    }
    glUniform3fv(program_->location("u_light_direction"), 1, glm::value_ptr(direction));
}

bool AliasFaceDrawer::begin(const npr::FrameView& view, const ShadingSettings& settings) {
    std::string error;
    program_ = build_variant(shading_variant(settings), error);
    if (!program_) return false;  // the default variant compiled: a driver failure
    program_->use();
    glUniformMatrix4fv(program_->location("u_view_projection"), 1, GL_FALSE,
                       glm::value_ptr(view.view_projection));
    set_shading_uniforms(*program_, settings);
    add_fullbright_ = settings.mode != ShadingMode::object_id;
    classic::begin_alias_face_culling();
    return true;
}

void AliasFaceDrawer::draw(const npr::FrameView& view, const nqr_entity& entity,
                           const classic::AliasModelGpu& model, GLuint skin_texture,
                           GLuint fullbright_texture, const glm::vec3& kd_average) {
    if (!program_ || skin_texture == 0) return;
    const glm::mat4 model_matrix = npr::mat4_from(entity.model_matrix);
    glUniformMatrix4fv(program_->location("u_model"), 1, GL_FALSE, entity.model_matrix);
    const glm::mat3 to_world = glm::inverseTranspose(glm::mat3(model_matrix));
    glUniformMatrix3fv(program_->location("u_normal_to_world"), 1, GL_FALSE,
                       glm::value_ptr(to_world));
    const glm::mat3 to_view = npr::normal_to_view(view, model_matrix);
    glUniformMatrix3fv(program_->location("u_normal_to_view"), 1, GL_FALSE,
                       glm::value_ptr(to_view));
    classic::set_alias_pose_uniforms(*program_, model, entity, kUnitPoses);
    set_entity_light_uniforms(*program_, entity);
    set_light_direction(entity);
    glUniform3fv(program_->location("u_kd_average"), 1, glm::value_ptr(kd_average));
    const float alpha = npr::entity_alpha(entity.alpha);
    glUniform1f(program_->location("u_alpha"), alpha);
    glUniform1f(program_->location("u_alpha_cutoff"), model.holey() ? kHoleyAlphaCutoff : 0.0f);

    glActiveTexture(GL_TEXTURE0 + kUnitSkin);
    glBindTexture(GL_TEXTURE_2D, skin_texture);
    glActiveTexture(GL_TEXTURE0 + kUnitFullbright);
    const bool add_fullbright = fullbright_texture != 0 && add_fullbright_;
    glBindTexture(GL_TEXTURE_2D, add_fullbright ? fullbright_texture : black_.id());
    glBindVertexArray(model.vertex_array());
    classic::draw_alias_elements(model.index_count(), alpha < 1.0f);
}

void AliasFaceDrawer::end() {
    classic::end_alias_face_pass();
}

void AliasFaceDrawer::draw_entity(const npr::FrameView& view, const nqr_entity& entity,
                                  const classic::AliasModelGpu& model, GLuint skin_texture,
                                  GLuint fullbright_texture, const glm::vec3& kd_average,
                                  const ShadingSettings& settings) {
    if (skin_texture == 0 || !begin(view, settings)) return;
    draw(view, entity, model, skin_texture, fullbright_texture, kd_average);
    end();
}

}  // namespace nq::npr::technical

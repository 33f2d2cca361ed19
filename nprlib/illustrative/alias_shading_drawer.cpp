#include "illustrative/alias_shading_drawer.h"

#include <epoxy/gl.h>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "abi/abi_access.h"
#include "abi/frame_view.h"
#include "classic/alias_pass_state.h"
#include "classic/alias_pose_glsl.h"
#include "gl/texture_upload.h"

namespace nq::npr::illustrative {
namespace {

constexpr char kHeader[] = "#version 330 core\n";
constexpr char kVertexBody[] = R"(
layout(location = 0) in uint a_pose_vertex;
layout(location = 1) in vec2 a_uv;
layout(location = 2) in uint a_normal_slot;
uniform samplerBuffer u_normals;
uniform int u_normal_slots;
uniform mat4 u_model;
uniform mat4 u_view_projection;
uniform mat3 u_normal_to_world;
uniform mat3 u_normal_to_view;
uniform vec3 u_eye;
out vec2 v_uv;
out vec3 v_world_position;
out vec3 v_world_normal;
out vec3 v_view_normal;
out vec3 v_cube_n;
out vec3 v_cube_back;
out float v_height;
vec3 unit_or_up(vec3 v) {
    float len2 = dot(v, v);
    return len2 > 1e-12 ? v * inversesqrt(len2) : vec3(0.0, 0.0, 1.0);
}
vec3 slot_normal(int pose) {
    return texelFetch(u_normals, pose * u_normal_slots + int(a_normal_slot)).xyz * 2.0 - 1.0;
}
void main() {
    vec3 position = pose_position(int(a_pose_vertex));
    vec3 normal = mix(slot_normal(u_pose0), slot_normal(u_pose1), u_lerp);
    vec4 world = u_model * vec4(position, 1.0);
    gl_Position = u_view_projection * world;
    v_uv = a_uv;
    v_world_position = world.xyz;
    v_world_normal = u_normal_to_world * normal;
    v_view_normal = u_normal_to_view * normal;
    v_cube_n = ill_ambient_cube(unit_or_up(v_world_normal));
    v_cube_back = ill_ambient_cube(-unit_or_up(u_eye - world.xyz));
    v_height = position.z;
}
)";

constexpr char kFragmentBody[] = R"(
in vec2 v_uv;
in vec3 v_world_position;
in vec3 v_world_normal;
in vec3 v_view_normal;
in vec3 v_cube_n;
in vec3 v_cube_back;
in float v_height;
uniform sampler2D u_skin;
uniform sampler2D u_fullbright;
uniform sampler2D u_masks;
uniform vec3 u_eye;
uniform float u_alpha;
uniform float u_alpha_cutoff;
uniform float u_team_saturation;
uniform vec3 u_height_gradient;  // on, lowest z, 1 / (highest - lowest)
uniform float u_height_floor;
layout(location = 0) out vec4 o_color;
layout(location = 1) out vec4 o_normal;
vec3 unit_or_up(vec3 v) {
    float len2 = dot(v, v);
    return len2 > 1e-12 ? v * inversesqrt(len2) : vec3(0.0, 0.0, 1.0);
}
vec3 saturate_by(vec3 c, float amount) {
    float luma = dot(c, vec3(0.299, 0.587, 0.114));
    return clamp(mix(vec3(luma), c, amount), 0.0, 1.0);
}
void main() {
    vec4 texel = texture(u_skin, v_uv);
#ifdef ILL_CUTOUT
    if (texel.a < u_alpha_cutoff) discard;  // cutoff 0: never
#endif
    vec4 masks = texture(u_masks, v_uv);
    vec3 kd = saturate_by(texel.rgb, mix(1.0, u_team_saturation, masks.a));
    if (u_height_gradient.x > 0.5) {
        float t = clamp((v_height - u_height_gradient.y) * u_height_gradient.z, 0.0, 1.0);
        kd *= mix(u_height_floor, 1.0, t);
    }
    vec3 n = unit_or_up(v_world_normal);
    vec3 v = unit_or_up(u_eye - v_world_position);
    vec3 ambient_light;
    vec3 shaded =
        ill_shade(kd, v_world_position, n, v, masks, v_cube_n, v_cube_back, ambient_light);
    vec3 glow = ill_final_colour() ? texture(u_fullbright, v_uv).rgb : vec3(0.0);
    o_color = vec4(shaded + glow, u_alpha);
    o_normal = vec4(unit_or_up(v_view_normal) * 0.5 + 0.5,
                    ill_ambient_share(ambient_light, shaded + glow));
}
)";

constexpr int kUnitSkin = 0;
constexpr int kUnitFullbright = 1;
constexpr int kUnitPoses = 2;
constexpr int kUnitNormals = 3;
constexpr int kUnitMasks = 4;
constexpr int kUnitWarp = 5;
constexpr float kHoleyAlphaCutoff = 0.666f;  // as the classic drawer

void bind(int unit, GLenum target, GLuint texture) {
    glActiveTexture(GL_TEXTURE0 + unit);
    glBindTexture(target, texture);
}

}  // namespace

bool AliasShadingDrawer::init(gl::ObjectTracker* tracker, std::string& error) {
    reset();
    tracker_ = tracker;
    black_ = gl::create_solid_texture(tracker, 0, 0, 0, 0);
    // k_s = 1, mid exponent, k_r = 1, no team colour: what ill_skin_masks 0 draws.
    neutral_masks_ = gl::create_solid_texture(tracker, 255, 128, 255, 0);
    // The general form is every other's fallback; the default settings' forms are built now so
    // that no frame waits for a compile. Others (gamma != 1) are built when first drawn.
    if (!build_variant(ShadingVariant{}, error)) return false;
    for (int lights = 0; lights <= int(NQR_MAX_ENTITY_LIGHTS); ++lights) {
        if (!build_variant({false, lights, false}, error)) return false;
    }
    return true;
}

bool AliasShadingDrawer::build_variant(const ShadingVariant& variant, std::string& error) {
    VariantProgram& slot = variants_[variant_index(variant)];
    const std::string vertex =
        std::string(kHeader) + classic::kAliasPoseLibrary + kAmbientCubeLibrary + kVertexBody;
    const std::string fragment =
        std::string(kHeader) + shading_defines(variant) + kIllustrativeLibrary + kFragmentBody;
    gl::ProgramBuild build = gl::Program::build(
        {"illustrative alias models", vertex.c_str(), fragment.c_str()}, tracker_);
    if (!build.ok()) {
        slot.build_failed = true;
        error = build.error;
        return false;
    }
    slot.program = std::move(build.program);
    gl::bind_sampler_units(slot.program,
                           {"u_skin", "u_fullbright", "u_poses", "u_normals", "u_masks", "u_warp"});
    return true;
}

void AliasShadingDrawer::reset() {
    for (VariantProgram& slot : variants_) slot = VariantProgram{};
    current_ = nullptr;
    black_.reset();
    neutral_masks_.reset();
    view_ = nullptr;
    settings_ = nullptr;
}

bool AliasShadingDrawer::begin(const npr::FrameView& view, const IllustrativeSettings& settings,
                               GLuint default_warp) {
    if (!variants_[kShadingVariants - 1].program) return false;
    view_ = &view;
    settings_ = &settings;
    default_warp_ = default_warp;
    ++pass_;
    current_ = nullptr;
    classic::begin_alias_face_culling();
    return true;
}

// The variant's program in use with this pass's uniforms; the general one when it cannot build.
gl::Program& AliasShadingDrawer::use_variant(const ShadingVariant& variant) {
    VariantProgram* slot = &variants_[variant_index(variant)];
    if (!slot->program && !slot->build_failed) {
        std::string ignored;  // the general form draws the same picture
        build_variant(variant, ignored);
        current_ = nullptr;  // building may have changed the program in use
    }
    if (!slot->program) slot = &variants_[kShadingVariants - 1];
    if (current_ != &slot->program) {
        slot->program.use();
        current_ = &slot->program;
    }
    if (slot->pass_uniforms_set != pass_) {
        set_pass_uniforms(slot->program);
        slot->pass_uniforms_set = pass_;
    }
    return slot->program;
}

void AliasShadingDrawer::set_pass_uniforms(gl::Program& program) {
    glUniformMatrix4fv(program.location("u_view_projection"), 1, GL_FALSE,
                       glm::value_ptr(view_->view_projection));
    glUniform3fv(program.location("u_eye"), 1, glm::value_ptr(view_->eye));
    set_illustrative_uniforms(program, *settings_);
    glUniform1f(program.location("u_height_floor"), settings_->height_gradient_floor);
}

void AliasShadingDrawer::draw(const npr::FrameView& view, const nqr_entity& entity,
                              const classic::AliasModelGpu& gpu, const IllustrativeModel& model,
                              const AliasShadingTextures& textures,
                              const MaterialParams& material) {
    if (!settings_ || textures.skin == 0) return;
    const EntityShading shading = entity_shading(entity, *settings_);
    gl::Program& program =
        use_variant(shading_variant(*settings_, shading.lights.count, gpu.holey()));
    const glm::mat4 model_matrix = npr::mat4_from(entity.model_matrix);
    glUniformMatrix4fv(program.location("u_model"), 1, GL_FALSE, entity.model_matrix);
    const glm::mat3 to_world = glm::inverseTranspose(glm::mat3(model_matrix));
    glUniformMatrix3fv(program.location("u_normal_to_world"), 1, GL_FALSE,
                       glm::value_ptr(to_world));
    const glm::mat3 to_view = npr::normal_to_view(view, model_matrix);
    glUniformMatrix3fv(program.location("u_normal_to_view"), 1, GL_FALSE, glm::value_ptr(to_view));
    classic::set_alias_pose_uniforms(program, gpu, entity, kUnitPoses);
    glUniform1i(program.location("u_normal_slots"), static_cast<GLint>(model.normal_slots()));
    set_entity_lighting(program, shading, material, *settings_);
    // Shirt and pants stay saturated on player-coloured models only (the team read).
    glUniform1f(program.location("u_team_saturation"),
                entity.has_translation ? settings_->team_saturation : 1.0f);
    const float height_span = model.height_max() - model.height_min();
    glUniform3f(program.location("u_height_gradient"), settings_->height_gradient ? 1.0f : 0.0f,
                model.height_min(), height_span > 0.0f ? 1.0f / height_span : 0.0f);
    const float alpha = npr::entity_alpha(entity.alpha);
    glUniform1f(program.location("u_alpha"), alpha);
    glUniform1f(program.location("u_alpha_cutoff"), gpu.holey() ? kHoleyAlphaCutoff : 0.0f);

    bind(kUnitSkin, GL_TEXTURE_2D, textures.skin);
    const bool glow = textures.fullbright != 0 && material.self_illum;
    bind(kUnitFullbright, GL_TEXTURE_2D, glow ? textures.fullbright : black_.id());
    bind(kUnitNormals, GL_TEXTURE_BUFFER, model.normal_texture());
    const bool masks = textures.masks != 0 && settings_->skin_masks;
    bind(kUnitMasks, GL_TEXTURE_2D, masks ? textures.masks : neutral_masks_.id());
    bind(kUnitWarp, GL_TEXTURE_2D, textures.warp ? textures.warp : default_warp_);
    glBindVertexArray(model.vertex_array());
    classic::draw_alias_elements(model.index_count(), alpha < 1.0f);
}

void AliasShadingDrawer::end() {
    classic::end_alias_face_pass();
    current_ = nullptr;
    view_ = nullptr;
    settings_ = nullptr;
}

}  // namespace nq::npr::illustrative

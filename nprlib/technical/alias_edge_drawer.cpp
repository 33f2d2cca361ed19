#include "technical/alias_edge_drawer.h"

#include <epoxy/gl.h>

#include <algorithm>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "classic/abi_access.h"
#include "classic/alias_pose_glsl.h"
#include "technical/alias_pose.h"
#include "technical/shading_glsl.h"

namespace nq::npr::technical {
namespace {

// After the pose, shading and edge libraries. The colour is shaded at this vertex's own end.
constexpr char kVertexBody[] = R"(
layout(location = 0) in vec3 a_own;
layout(location = 1) in vec3 a_other;
layout(location = 2) in vec2 a_uv;
layout(location = 3) in uint a_packed;  // side | kind << 1 | MDL vertex << 3
uniform sampler2D u_skin;
uniform mat4 u_model;
uniform mat4 u_model_view;
uniform mat3 u_normal_to_world;
uniform vec3 u_eye_world;
uniform vec3 u_light_direction;
void main() {
    int side = int(a_packed & 1u);
    int kind = int((a_packed >> 1u) & 3u);
    vec3 normal = u_normal_to_world * pose_normal(int(a_packed >> 3u));
    float len = length(normal);
    normal = len > 1e-6 ? normal / len : vec3(0.0, 0.0, 1.0);
    vec3 shaded = technical_shade(surface_kd(u_skin, a_uv, 0.0), normal, u_light_direction, a_own.z);
    vec3 world = (u_model * vec4(a_own, 1.0)).xyz;
    g_color = edge_color(kind, shaded, length(world - u_eye_world));
    gl_Position = edge_corner_at((u_model_view * vec4(a_own, 1.0)).xyz,
                                 (u_model_view * vec4(a_other, 1.0)).xyz, kind, side);
}
)";

constexpr int kUnitSkin = 0;
constexpr int kUnitPoses = 1;
// One push holds a frame's edges: 32 MB of ring, 8 MB (200k quad corners) a push.
constexpr size_t kStreamBytes = size_t{32} << 20;

glm::vec3 light_direction(const nqr_entity& entity) {
    const nqr_entity_light& light = entity.light;
    if (light.size < sizeof(nqr_entity_light)) return {0.0f, 0.0f, 1.0f};
    const glm::vec3 direction = glm::make_vec3(light.direction);
    const float len = glm::length(direction);
    return len > 1e-6f ? direction / len : glm::vec3(0.0f, 0.0f, 1.0f);
}

uint16_t unit_short(float value) {
    return static_cast<uint16_t>(std::clamp(value, 0.0f, 1.0f) * 65535.0f + 0.5f);
}

std::vector<uint32_t> quad_pattern(size_t quads) {
    std::vector<uint32_t> indices;
    indices.reserve(quads * 6);
    for (uint32_t q = 0; q < quads; ++q) {
        const uint32_t v = q * 4;
        indices.insert(indices.end(), {v, v + 1, v + 2, v, v + 2, v + 3});
    }
    return indices;
}

}  // namespace

bool AliasEdgeDrawer::init(gl::ObjectTracker* tracker, std::string& error) {
    reset();
    const std::string vertex = std::string("#version 330 core\n") + classic::kAliasPoseLibrary +
                               kShadingLibrary + kEdgeLibrary + kEdgeVertexLibrary + kVertexBody;
    gl::ProgramBuild build =
        gl::Program::build({"technical alias edges", vertex.c_str(), kEdgeFragment}, tracker);
    if (!build.ok()) {
        error = build.error;
        return false;
    }
    program_ = std::move(build.program);
    gl::bind_sampler_units(program_, {"u_skin", "u_poses"});
    glUseProgram(0);
    if (!stream_.create(tracker, kStreamBytes)) {
        error = "technical alias edges: cannot create the edge stream buffer";
        return false;
    }
    max_edges_ = stream_.max_push() / (4 * sizeof(Corner));
    const std::vector<uint32_t> indices = quad_pattern(max_edges_);
    quad_indices_ = gl::Buffer::create(tracker);
    vertex_array_ = gl::VertexArray::create(tracker);
    glBindVertexArray(vertex_array_.id());
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, quad_indices_.id());
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indices.size() * 4),
                 indices.data(), GL_STATIC_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, stream_.id());
    const GLsizei stride = sizeof(Corner);
    const auto at = [](size_t offset) { return reinterpret_cast<const void*>(offset); };
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, at(offsetof(Corner, own)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride, at(offsetof(Corner, other)));
    glEnableVertexAttribArray(2);
    glVertexAttribPointer(2, 2, GL_UNSIGNED_SHORT, GL_TRUE, stride, at(offsetof(Corner, uv)));
    glEnableVertexAttribArray(3);
    glVertexAttribIPointer(3, 1, GL_UNSIGNED_INT, stride, at(offsetof(Corner, packed)));
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    corners_.reserve(4096);
    found_.reserve(1024);
    return true;
}

void AliasEdgeDrawer::reset() {
    vertex_array_.reset();
    quad_indices_.reset();
    stream_.reset();
    program_.reset();
    corners_.clear();
    uploaded_ = false;
}

void AliasEdgeDrawer::begin_frame() {
    corners_.clear();
    uploaded_ = false;
}

EdgeSpan AliasEdgeDrawer::add_entity(const nqr_entity& entity, const AliasEdgeMesh& mesh,
                                     const glm::vec3* pose, const EdgeSettings& settings) {
    EdgeSpan span{corners_.size() / 4, 0};
    const EdgeQuery query = plan_edge_query(mesh, settings);
    if (!query.any() || !pose || uploaded_) return span;
    found_.clear();
    mesh.find_edges(pose, glm::make_vec3(entity.eye_model), query, found_);
    // What one push cannot hold is left out (tens of thousands of edges in one frame).
    const size_t room = max_edges_ - std::min(max_edges_, span.first_edge);
    span.edge_count = std::min(found_.size(), room);
    const std::span<const glm::vec2> uv = mesh.skin_coords();
    const auto corner = [&](const glm::vec3& own, const glm::vec3& other, uint32_t vertex,
                            uint32_t kind, uint32_t side) {
        corners_.push_back({own, other, {unit_short(uv[vertex].x), unit_short(uv[vertex].y)},
                            side | kind << 1 | vertex << 3});
    };
    for (size_t i = 0; i < span.edge_count; ++i) {
        const FoundEdge& e = found_[i];
        const uint32_t kind = static_cast<uint32_t>(e.kind);
        const glm::vec3 &a = pose[e.v0], &b = pose[e.v1];
        corner(a, b, e.v0, kind, 0);
        corner(a, b, e.v0, kind, 1);
        corner(b, a, e.v1, kind, 0);
        corner(b, a, e.v1, kind, 1);
    }
    return span;
}

void AliasEdgeDrawer::upload() {
    uploaded_ = true;
    if (corners_.empty()) return;
    const size_t offset = stream_.push(corners_.data(), corners_.size() * sizeof(Corner),
                                       sizeof(Corner));
    base_vertex_ = offset == gl::StreamBuffer::kNoSpace ? 0 : offset / sizeof(Corner);
    if (offset == gl::StreamBuffer::kNoSpace) corners_.clear();  // cannot happen: add_entity caps
}

void AliasEdgeDrawer::begin(const classic::FrameView& view,
                            const EdgeFrameUniforms& frame_uniforms,
                            const TechnicalSettings& settings) {
    program_.use();
    glUniform3fv(program_.location("u_eye_world"), 1, glm::value_ptr(view.eye));
    set_shading_uniforms(program_, settings.shading);
    set_edge_uniforms(program_, settings.edges, frame_uniforms);
    glBindVertexArray(vertex_array_.id());
}

void AliasEdgeDrawer::draw_entity(const classic::FrameView& view, const nqr_entity& entity,
                                  const classic::AliasModelGpu& faces, GLuint skin_texture,
                                  EdgeSpan span) {
    if (span.edge_count == 0 || !uploaded_ || !classic::has_known_prefix(&entity)) return;
    const glm::mat4 model = classic::mat4_from(entity.model_matrix);
    const glm::mat4 model_view = view.view * model;
    const glm::mat3 normal_to_world = glm::inverseTranspose(glm::mat3(model));
    glUniformMatrix4fv(program_.location("u_model"), 1, GL_FALSE, entity.model_matrix);
    glUniformMatrix4fv(program_.location("u_model_view"), 1, GL_FALSE,
                       glm::value_ptr(model_view));
    glUniformMatrix3fv(program_.location("u_normal_to_world"), 1, GL_FALSE,
                       glm::value_ptr(normal_to_world));
    const glm::vec3 light = light_direction(entity);
    glUniform3fv(program_.location("u_light_direction"), 1, glm::value_ptr(light));
    set_entity_light_uniforms(program_, entity);
    classic::set_alias_pose_uniforms(program_, faces, entity, kUnitPoses);
    glActiveTexture(GL_TEXTURE0 + kUnitSkin);
    glBindTexture(GL_TEXTURE_2D, skin_texture);
    glDrawElementsBaseVertex(GL_TRIANGLES, static_cast<GLsizei>(span.edge_count * 6),
                             GL_UNSIGNED_INT, nullptr,
                             static_cast<GLint>(base_vertex_ + span.first_edge * 4));
}

void AliasEdgeDrawer::end() {
    glBindVertexArray(0);
    glUseProgram(0);
    glActiveTexture(GL_TEXTURE0);
}

void AliasEdgeDrawer::draw_entity(const classic::FrameView& view,
                                  const EdgeFrameUniforms& frame_uniforms,
                                  const nqr_entity& entity, const classic::AliasModelGpu& faces,
                                  const AliasEdgeMesh& edges, GLuint skin_texture,
                                  const TechnicalSettings& settings) {
    if (!program_ || !classic::has_known_prefix(&entity)) return;
    pose_.resize(edges.vertex_count());
    blend_alias_pose(faces.model(), entity, pose_.data());
    begin_frame();
    const EdgeSpan span = add_entity(entity, edges, pose_.data(), settings.edges);
    upload();
    begin(view, frame_uniforms, settings);
    draw_entity(view, entity, faces, skin_texture, span);
    end();
}

}  // namespace nq::npr::technical

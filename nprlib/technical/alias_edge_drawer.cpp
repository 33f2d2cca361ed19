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

// The shading pass, after the pose and shading libraries: one point per MDL vertex of one
// entity (gl_VertexID - u_first_row is the MDL vertex), captured, never rasterised.
constexpr char kShadingBody[] = R"(
layout(location = 0) in vec2 a_uv;
uniform int u_first_row;
uniform sampler2D u_skin;
uniform mat4 u_model;
uniform mat4 u_model_view;
uniform mat3 u_normal_to_world;
uniform vec3 u_eye_world;
uniform vec3 u_light_direction;
out vec4 f_view;    // view-space position, distance from the eye
out vec4 f_shaded;  // the surface colour shaded there
void main() {
    int vertex = gl_VertexID - u_first_row;
    vec3 position = pose_position(vertex);
    vec3 normal = u_normal_to_world * pose_normal(vertex);
    float len = length(normal);
    normal = len > 1e-6 ? normal / len : vec3(0.0, 0.0, 1.0);
    vec3 shaded = technical_shade(surface_kd(u_skin, a_uv, 0.0), normal, u_light_direction,
                                  position.z);
    vec3 world = (u_model * vec4(position, 1.0)).xyz;
    f_view = vec4((u_model_view * vec4(position, 1.0)).xyz, length(world - u_eye_world));
    f_shaded = vec4(shaded, 1.0);
    gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
}
)";
constexpr const char* kShadedOutputs[] = {"f_view", "f_shaded"};
constexpr int kShadedTexelsPerVertex = 2;

// The quads, after the edge libraries: each vertex reads its edge's two ends.
constexpr char kQuadBody[] = R"(
layout(location = 0) in uvec2 a_ends;  // own, other: rows of u_shaded
layout(location = 1) in uint a_side_and_kind;
uniform samplerBuffer u_shaded;
void main() {
    int side = int(a_side_and_kind & 1u);
    int kind = int(a_side_and_kind >> 1u);
    vec4 own = texelFetch(u_shaded, int(a_ends.x) * 2);
    vec4 shaded = texelFetch(u_shaded, int(a_ends.x) * 2 + 1);
    vec4 other = texelFetch(u_shaded, int(a_ends.y) * 2);
    g_color = edge_color(kind, shaded.rgb, own.w);
    gl_Position = edge_corner_at(own.xyz, other.xyz, kind, side);
}
)";

constexpr int kUnitSkin = 0;
constexpr int kUnitPoses = 1;
constexpr int kUnitShaded = 0;
// Quad corners: 16 MB of ring, 4 MB (350k corners) a push; skin coordinates ride along.
constexpr size_t kStreamBytes = size_t{16} << 20;

glm::vec3 light_direction(const nqr_entity& entity) {
    const nqr_entity_light& light = entity.light;
    if (light.size < sizeof(nqr_entity_light)) return {0.0f, 0.0f, 1.0f};
    const glm::vec3 direction = glm::make_vec3(light.direction);
    const float len = glm::length(direction);
    return len > 1e-6f ? direction / len : glm::vec3(0.0f, 0.0f, 1.0f);
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

const void* at(size_t offset) {
    return reinterpret_cast<const void*>(offset);
}

}  // namespace

bool AliasEdgeDrawer::init(gl::ObjectTracker* tracker, std::string& error) {
    reset();
    const std::string shading = std::string("#version 330 core\n") + classic::kAliasPoseLibrary +
                                kShadingLibrary + kShadingBody;
    gl::ProgramSource shading_source{"technical edge vertices", shading.c_str(), nullptr};
    shading_source.feedback_varyings = kShadedOutputs;
    shading_source.feedback_count = 2;
    gl::ProgramBuild shading_build = gl::Program::build(shading_source, tracker);
    const std::string quads =
        std::string("#version 330 core\n") + kEdgeLibrary + kEdgeVertexLibrary + kQuadBody;
    gl::ProgramBuild quads_build =
        gl::Program::build({"technical alias edges", quads.c_str(), kEdgeFragment}, tracker);
    if (!shading_build.ok() || !quads_build.ok()) {
        error = shading_build.ok() ? quads_build.error : shading_build.error;
        return false;
    }
    shading_ = std::move(shading_build.program);
    quads_ = std::move(quads_build.program);
    gl::bind_sampler_units(shading_, {"u_skin", "u_poses"});
    gl::bind_sampler_units(quads_, {"u_shaded"});
    glUseProgram(0);
    if (!corner_stream_.create(tracker, kStreamBytes)) {
        error = "technical alias edges: cannot create the edge stream buffer";
        return false;
    }
    max_edges_ = corner_stream_.max_push() / (4 * sizeof(Corner) + 2 * sizeof(uint32_t));

    shaded_ = gl::Buffer::create(tracker);
    glBindBuffer(GL_TEXTURE_BUFFER, shaded_.id());
    glBufferData(GL_TEXTURE_BUFFER, GLsizeiptr{kMaxShadedVertices} * kShadedTexelsPerVertex * 16,
                 nullptr, GL_DYNAMIC_COPY);
    shaded_texture_ = gl::Texture::create(tracker);
    glBindTexture(GL_TEXTURE_BUFFER, shaded_texture_.id());
    glTexBuffer(GL_TEXTURE_BUFFER, GL_RGBA32F, shaded_.id());
    glBindTexture(GL_TEXTURE_BUFFER, 0);
    glBindBuffer(GL_TEXTURE_BUFFER, 0);

    const std::vector<uint32_t> indices = quad_pattern(max_edges_);
    quad_indices_ = gl::Buffer::create(tracker);
    quads_array_ = gl::VertexArray::create(tracker);
    glBindVertexArray(quads_array_.id());
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, quad_indices_.id());
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indices.size() * 4),
                 indices.data(), GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);  // pointed at each frame's corners by upload()
    glEnableVertexAttribArray(1);
    points_array_ = gl::VertexArray::create(tracker);
    glBindVertexArray(points_array_.id());
    glEnableVertexAttribArray(0);
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    corners_.reserve(4096);
    found_.reserve(1024);
    shaded_entities_.reserve(256);
    return true;
}

void AliasEdgeDrawer::reset() {
    points_array_.reset();
    quads_array_.reset();
    quad_indices_.reset();
    shaded_texture_.reset();
    shaded_.reset();
    corner_stream_.reset();
    quads_.reset();
    shading_.reset();
    begin_frame();
}

void AliasEdgeDrawer::begin_frame() {
    corners_.clear();
    skin_coords_.clear();
    shaded_entities_.clear();
    shaded_rows_ = 0;
    uploaded_ = false;
}

EdgeSpan AliasEdgeDrawer::add_entity(const nqr_entity& entity, const classic::AliasModelGpu& faces,
                                     GLuint skin_texture, const AliasEdgeMesh& mesh,
                                     const glm::vec3* pose, const EdgeSettings& settings) {
    EdgeSpan span{corners_.size() / 4, 0};
    const EdgeQuery query = plan_edge_query(mesh, settings);
    const uint32_t rows = mesh.vertex_count();
    if (!query.any() || !pose || uploaded_ || rows > kMaxShadedVertices - shaded_rows_) {
        return span;
    }
    found_.clear();
    mesh.find_edges(pose, glm::make_vec3(entity.eye_model), query, found_);
    // What one push cannot hold is left out (tens of thousands of edges in one frame).
    const size_t room = max_edges_ - std::min(max_edges_, span.first_edge);
    span.edge_count = std::min(found_.size(), room);
    if (span.edge_count == 0) return span;
    const uint32_t first = shaded_rows_;
    for (size_t i = 0; i < span.edge_count; ++i) {
        const FoundEdge& e = found_[i];
        const uint32_t kind = static_cast<uint32_t>(e.kind) << 1;
        const uint32_t a = first + e.v0, b = first + e.v1;
        corners_.push_back({a, b, kind | 0u});
        corners_.push_back({a, b, kind | 1u});
        // Seen from the far end the sides swap: (b, 0) lies beside (a, 1).
        corners_.push_back({b, a, kind | 0u});
        corners_.push_back({b, a, kind | 1u});
    }
    shaded_entities_.push_back({&entity, &faces, skin_texture, first});
    for (const glm::vec2& uv : mesh.skin_coords()) skin_coords_.push_back(uv);
    shaded_rows_ += rows;
    return span;
}

void AliasEdgeDrawer::upload(const classic::FrameView& view, const ShadingSettings& shading) {
    uploaded_ = true;
    if (corners_.empty()) return;
    const size_t offset = corner_stream_.push(corners_.data(), corners_.size() * sizeof(Corner), 4);
    if (offset == gl::StreamBuffer::kNoSpace) {
        corners_.clear();  // cannot happen: add_entity caps the batch
        return;
    }
    glBindVertexArray(quads_array_.id());
    glBindBuffer(GL_ARRAY_BUFFER, corner_stream_.id());
    glVertexAttribIPointer(0, 2, GL_UNSIGNED_INT, sizeof(Corner),
                           at(offset + offsetof(Corner, own)));
    glVertexAttribIPointer(1, 1, GL_UNSIGNED_INT, sizeof(Corner),
                           at(offset + offsetof(Corner, side_and_kind)));
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glBindVertexArray(0);
    shade_vertices(view, shading);
}

void AliasEdgeDrawer::shade_vertices(const classic::FrameView& view,
                                     const ShadingSettings& shading) {
    const size_t uv_offset = corner_stream_.push(
        skin_coords_.data(), skin_coords_.size() * sizeof(glm::vec2), sizeof(glm::vec2));
    if (uv_offset == gl::StreamBuffer::kNoSpace) {
        corners_.clear();
        return;
    }
    shading_.use();
    set_shading_uniforms(shading_, shading);
    glUniform3fv(shading_.location("u_eye_world"), 1, glm::value_ptr(view.eye));
    glBindVertexArray(points_array_.id());
    glBindBuffer(GL_ARRAY_BUFFER, corner_stream_.id());
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, sizeof(glm::vec2), at(uv_offset));
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glEnable(GL_RASTERIZER_DISCARD);
    glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, shaded_.id());
    glBeginTransformFeedback(GL_POINTS);
    for (const ShadedEntity& shaded : shaded_entities_) {
        const nqr_entity& entity = *shaded.entity;
        const glm::mat4 model = classic::mat4_from(entity.model_matrix);
        const glm::mat4 model_view = view.view * model;
        const glm::mat3 normal_to_world = glm::inverseTranspose(glm::mat3(model));
        glUniform1i(shading_.location("u_first_row"), static_cast<GLint>(shaded.first_row));
        glUniformMatrix4fv(shading_.location("u_model"), 1, GL_FALSE, entity.model_matrix);
        glUniformMatrix4fv(shading_.location("u_model_view"), 1, GL_FALSE,
                           glm::value_ptr(model_view));
        glUniformMatrix3fv(shading_.location("u_normal_to_world"), 1, GL_FALSE,
                           glm::value_ptr(normal_to_world));
        const glm::vec3 light = light_direction(entity);
        glUniform3fv(shading_.location("u_light_direction"), 1, glm::value_ptr(light));
        set_entity_light_uniforms(shading_, entity);
        classic::set_alias_pose_uniforms(shading_, *shaded.faces, entity, kUnitPoses);
        glActiveTexture(GL_TEXTURE0 + kUnitSkin);
        glBindTexture(GL_TEXTURE_2D, shaded.skin);
        glDrawArrays(GL_POINTS, static_cast<GLint>(shaded.first_row),
                     static_cast<GLsizei>(shaded.faces->model().num_vertices));
    }
    glEndTransformFeedback();
    glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, 0);
    glDisable(GL_RASTERIZER_DISCARD);
    glBindVertexArray(0);
    glUseProgram(0);
    glActiveTexture(GL_TEXTURE0);
}

void AliasEdgeDrawer::begin(const EdgeFrameUniforms& frame_uniforms, const EdgeSettings& settings) {
    quads_.use();
    set_edge_uniforms(quads_, settings, frame_uniforms);
    glActiveTexture(GL_TEXTURE0 + kUnitShaded);
    glBindTexture(GL_TEXTURE_BUFFER, shaded_texture_.id());
    glBindVertexArray(quads_array_.id());
}

void AliasEdgeDrawer::draw(EdgeSpan span) {
    if (span.edge_count == 0 || !uploaded_ || corners_.empty()) return;
    glDrawElementsBaseVertex(GL_TRIANGLES, static_cast<GLsizei>(span.edge_count * 6),
                             GL_UNSIGNED_INT, nullptr, static_cast<GLint>(span.first_edge * 4));
}

void AliasEdgeDrawer::end() {
    glBindVertexArray(0);
    glUseProgram(0);
    glBindTexture(GL_TEXTURE_BUFFER, 0);
    glActiveTexture(GL_TEXTURE0);
}

void AliasEdgeDrawer::draw_entity(const classic::FrameView& view,
                                  const EdgeFrameUniforms& frame_uniforms, const nqr_entity& entity,
                                  const classic::AliasModelGpu& faces, const AliasEdgeMesh& edges,
                                  GLuint skin_texture, const TechnicalSettings& settings) {
    if (!quads_ || !classic::has_known_prefix(&entity)) return;
    pose_.resize(edges.vertex_count());
    blend_alias_pose(faces.model(), entity, pose_.data());
    begin_frame();
    const EdgeSpan span =
        add_entity(entity, faces, skin_texture, edges, pose_.data(), settings.edges);
    upload(view, settings.shading);
    begin(frame_uniforms, settings.edges);
    draw(span);
    end();
}

}  // namespace nq::npr::technical

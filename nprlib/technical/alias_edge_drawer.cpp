#include "technical/alias_edge_drawer.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "classic/abi_access.h"
#include "classic/alias_pose_glsl.h"
#include "technical/shading_glsl.h"

namespace nq::npr::technical {
namespace {

// Per MDL vertex (gl_VertexID): the blended pose position, its view-space position, the shaded
// colour under it (for white addition and fade) and its distance from the eye in world units.
// (Shading here rather than per emitted edge in the geometry shader is faster on llvmpipe,
// which runs geometry shaders eight primitives at a time with every branch taken.)
constexpr char kVertexBody[] = R"(
layout(location = 0) in vec2 a_skin_coord;
uniform sampler2D u_skin;
uniform mat4 u_model;
uniform mat4 u_view;
uniform mat3 u_normal_to_world;
uniform vec3 u_eye_world;
uniform vec3 u_light_direction;
out EdgeVertex {
    vec3 model_position;
    vec3 view_position;
    vec3 shaded;
    float distance;
    flat int mdl_vertex;
} v_out;
void main() {
    vec3 position = pose_position(gl_VertexID);
    vec3 world = (u_model * vec4(position, 1.0)).xyz;
    vec3 normal = u_normal_to_world * pose_normal(gl_VertexID);
    float len = length(normal);
    normal = len > 1e-6 ? normal / len : vec3(0.0, 0.0, 1.0);
    vec3 kd = surface_kd(u_skin, a_skin_coord, 0.0);
    v_out.model_position = position;
    v_out.view_position = (u_view * vec4(world, 1.0)).xyz;
    v_out.shaded = technical_shade(kd, normal, u_light_direction, position.z);
    v_out.distance = length(world - u_eye_world);
    v_out.mdl_vertex = gl_VertexID;
    gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
}
)";

// Shared by both geometry shaders, after their layout lines and the edge library. Facing is
// tested in model space against the true eye, on the blended pose.
constexpr char kGeometryCommon[] = R"(
in EdgeVertex {
    vec3 model_position;
    vec3 view_position;
    vec3 shaded;
    float distance;
    flat int mdl_vertex;
} v_in[];
uniform vec3 u_eye_model;
const int NO_EDGE = -1;
bool faces_eye(vec3 normal, vec3 point) { return dot(normal, u_eye_model - point) > 0.0; }
bool degenerate(vec3 normal) { return dot(normal, normal) < 1e-10; }
void emit_between(int a, int b, int kind) {
    emit_edge(v_in[a].view_position, v_in[b].view_position,
              edge_color(kind, v_in[a].shaded, v_in[a].distance),
              edge_color(kind, v_in[b].shaded, v_in[b].distance), kind);
}
)";

// Input, per mesh edge: face0's third corner, the edge's ends v0 and v1, the neighbour's far
// corner (edge range of alias_edge_mesh.h); faces wind counter-clockwise seen from outside, so
// face0 is (v0, v1, third) and the neighbour (v1, v0, far). One invocation, at most one quad.
constexpr char kTrueEdgesBody[] = R"(
#define SILHOUETTES_OFF 0
#define SILHOUETTES_HERE 1
#define SILHOUETTES_BY_BACKFACE 2
uniform float u_cos_crease;
uniform int u_silhouettes;
uniform int u_find_creases;

int silhouette_kind() { return u_silhouettes == SILHOUETTES_HERE ? EDGE_SILHOUETTE : NO_EDGE; }

int classify_edge() {
    vec3 third = v_in[0].model_position, p0 = v_in[1].model_position;
    vec3 p1 = v_in[2].model_position, far = v_in[3].model_position;
    // An open border (the far corner is face0's own third corner) outlines from either side.
    if (v_in[3].mdl_vertex == v_in[0].mdl_vertex) return silhouette_kind();
    vec3 n0 = cross(p1 - p0, third - p0), n1 = cross(p0 - p1, far - p1);
    if (degenerate(n0) || degenerate(n1)) return NO_EDGE;
    bool front0 = faces_eye(n0, p0), front1 = faces_eye(n1, p1);
    // A silhouette is no crease, unless silhouettes are off.
    if (front0 != front1 && u_silhouettes != SILHOUETTES_OFF) return silhouette_kind();
    if (u_find_creases == 0 || !(front0 || front1)) return NO_EDGE;
    if (dot(normalize(n0), normalize(n1)) >= u_cos_crease) return NO_EDGE;
    // Convex (ridge) when the neighbour's far corner lies behind face0's plane.
    return dot(n0, far - p0) < 0.0 ? EDGE_RIDGE : EDGE_VALLEY;
}

void main() {
    int kind = classify_edge();
    if (kind != NO_EDGE) emit_between(1, 2, kind);
}
)";

// The paper's back-face lines: all three edges of every back-facing triangle.
constexpr char kBackfaceBody[] = R"(
void main() {
    vec3 p0 = v_in[0].model_position;
    vec3 normal = cross(v_in[1].model_position - p0, v_in[2].model_position - p0);
    if (degenerate(normal) || faces_eye(normal, p0)) return;
    emit_between(0, 1, EDGE_BACKFACE);
    emit_between(1, 2, EDGE_BACKFACE);
    emit_between(2, 0, EDGE_BACKFACE);
}
)";

constexpr char kTrueEdgesLayout[] =
    "#version 330 core\n"
    "layout(lines_adjacency) in;\n"
    "layout(triangle_strip, max_vertices = 4) out;\n";
constexpr char kBackfaceLayout[] =
    "#version 330 core\n"
    "layout(triangles) in;\n"
    "layout(triangle_strip, max_vertices = 12) out;\n";

constexpr int kUnitSkin = 0;
constexpr size_t kCandidateRingBytes = size_t(1) << 20;
constexpr int kUnitPoses = 1;

// Which edges this model gets under the settings.
struct EdgePlan {
    bool silhouettes = false;  // true silhouettes from adjacency
    bool creases = false;
    bool backface_lines = false;  // in place of true silhouettes
};

// u_silhouettes: the SILHOUETTES_* constants of kTrueEdgesBody.
enum SilhouetteMode : int { kSilhouettesOff = 0, kSilhouettesHere = 1, kSilhouettesByBackface = 2 };

SilhouetteMode silhouette_mode(const EdgePlan& plan) {
    if (plan.silhouettes) return kSilhouettesHere;
    return plan.backface_lines ? kSilhouettesByBackface : kSilhouettesOff;
}

EdgePlan plan_edges(const AliasEdgeMesh& mesh, const EdgeSettings& s) {
    const bool fallback = s.backface_lines == BackfaceLines::always ||
                          (s.backface_lines == BackfaceLines::unclean_models && !mesh.clean());
    const bool has_adjacency = mesh.adjacency_index_count() > 0;
    EdgePlan plan;
    plan.backface_lines = s.silhouettes && fallback && mesh.triangle_index_count() > 0;
    plan.silhouettes = s.silhouettes && !fallback && has_adjacency;
    // Creases need trustworthy adjacency, unless back-face lines are refused altogether.
    plan.creases =
        s.creases && has_adjacency && (mesh.clean() || s.backface_lines == BackfaceLines::never);
    return plan;
}

glm::vec3 light_direction(const nqr_entity& entity) {
    const nqr_entity_light& light = entity.light;
    if (light.size < sizeof(nqr_entity_light)) return {0.0f, 0.0f, 1.0f};
    const glm::vec3 direction = glm::make_vec3(light.direction);
    const float len = glm::length(direction);
    return len > 1e-6f ? direction / len : glm::vec3(0.0f, 0.0f, 1.0f);
}

gl::ProgramBuild build_program(const char* name, const char* layout, const char* body,
                               gl::ObjectTracker* tracker) {
    const std::string vertex = std::string("#version 330 core\n") + classic::kAliasPoseLibrary +
                               kShadingLibrary + kVertexBody;
    const std::string geometry =
        std::string(layout) + kEdgeGeometryLibrary + kGeometryCommon + body;
    return gl::Program::build({name, vertex.c_str(), kEdgeFragment, geometry.c_str()}, tracker);
}

}  // namespace

bool AliasEdgeDrawer::init(gl::ObjectTracker* tracker, std::string& error) {
    gl::ProgramBuild true_edges =
        build_program("technical alias edges", kTrueEdgesLayout, kTrueEdgesBody, tracker);
    if (!true_edges.ok()) {
        error = true_edges.error;
        return false;
    }
    gl::ProgramBuild backface =
        build_program("technical alias back-face lines", kBackfaceLayout, kBackfaceBody, tracker);
    if (!backface.ok()) {
        error = backface.error;
        return false;
    }
    true_edges_ = std::move(true_edges.program);
    backface_lines_ = std::move(backface.program);
    if (!candidates_.create(tracker, kCandidateRingBytes)) {
        error = "technical alias edges: cannot create the candidate-edge stream buffer";
        return false;
    }
    gl::bind_sampler_units(true_edges_, {"u_skin", "u_poses"});
    gl::bind_sampler_units(backface_lines_, {"u_skin", "u_poses"});
    glUseProgram(0);
    return true;
}

void AliasEdgeDrawer::reset() {
    candidates_.reset();
    true_edges_.reset();
    backface_lines_.reset();
}

void AliasEdgeDrawer::set_entity_uniforms(gl::Program& program, const classic::FrameView& view,
                                          const EdgeFrameUniforms& frame_uniforms,
                                          const nqr_entity& entity,
                                          const classic::AliasModelGpu& faces,
                                          const TechnicalSettings& settings) {
    const glm::mat4 model = classic::mat4_from(entity.model_matrix);
    const glm::mat3 normal_to_world = glm::inverseTranspose(glm::mat3(model));
    glUniformMatrix4fv(program.location("u_model"), 1, GL_FALSE, entity.model_matrix);
    glUniformMatrix4fv(program.location("u_view"), 1, GL_FALSE, glm::value_ptr(view.view));
    glUniformMatrix3fv(program.location("u_normal_to_world"), 1, GL_FALSE,
                       glm::value_ptr(normal_to_world));
    glUniform3fv(program.location("u_eye_world"), 1, glm::value_ptr(view.eye));
    glUniform3fv(program.location("u_eye_model"), 1, entity.eye_model);
    const glm::vec3 light = light_direction(entity);
    glUniform3fv(program.location("u_light_direction"), 1, glm::value_ptr(light));
    set_shading_uniforms(program, settings.shading);
    set_entity_light_uniforms(program, entity);
    set_edge_uniforms(program, settings.edges, frame_uniforms);
    classic::set_alias_pose_uniforms(program, faces, entity, kUnitPoses);
}

void AliasEdgeDrawer::draw_true_edges(const nqr_entity& entity, const AliasEdgeMesh& edges,
                                      int silhouettes, bool creases, const EdgeSettings& settings) {
    const float angle = std::clamp(settings.crease_angle_degrees, 0.0f, 180.0f);
    const float cos_crease = std::cos(glm::radians(angle));
    glUniform1f(true_edges_.location("u_cos_crease"), cos_crease);
    glUniform1i(true_edges_.location("u_silhouettes"), silhouettes);
    glUniform1i(true_edges_.location("u_find_creases"), creases ? 1 : 0);
    const std::span<const uint32_t> candidates = edges.candidate_edges(entity, cos_crease, creases);
    if (candidates.empty()) return;
    const size_t offset = candidates_.push(candidates.data(), candidates.size_bytes(), 4);
    if (offset == gl::StreamBuffer::kNoSpace) {  // larger than the ring: every edge instead
        glDrawElements(GL_LINES_ADJACENCY, edges.edge_index_count(), GL_UNSIGNED_INT,
                       edges.edge_indices_offset());
        return;
    }
    // The VAO's element buffer is the mesh's own: borrow the slot for the stream, then give it
    // back.
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, candidates_.id());
    glDrawElements(GL_LINES_ADJACENCY, static_cast<GLsizei>(candidates.size()), GL_UNSIGNED_INT,
                   reinterpret_cast<const void*>(offset));
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, edges.index_buffer());
}

void AliasEdgeDrawer::draw_backface_lines(const AliasEdgeMesh& edges) {
    // emit_edge leaves EDGE_BACKFACE quads at their own depth: the front faces hide them.
    glDrawElements(GL_TRIANGLES, edges.triangle_index_count(), GL_UNSIGNED_INT,
                   edges.triangle_indices_offset());
}

void AliasEdgeDrawer::draw_entity(const classic::FrameView& view,
                                  const EdgeFrameUniforms& frame_uniforms, const nqr_entity& entity,
                                  const classic::AliasModelGpu& faces, const AliasEdgeMesh& edges,
                                  GLuint skin_texture, const TechnicalSettings& settings) {
    if (!true_edges_ || !classic::has_known_prefix(&entity)) return;
    const EdgePlan plan = plan_edges(edges, settings.edges);
    if (!plan.silhouettes && !plan.creases && !plan.backface_lines) return;
    glBindVertexArray(edges.vertex_array());
    if (plan.backface_lines) {
        backface_lines_.use();
        set_entity_uniforms(backface_lines_, view, frame_uniforms, entity, faces, settings);
        glActiveTexture(GL_TEXTURE0 + kUnitSkin);
        glBindTexture(GL_TEXTURE_2D, skin_texture);
        draw_backface_lines(edges);
    }
    if (plan.silhouettes || plan.creases) {
        true_edges_.use();
        set_entity_uniforms(true_edges_, view, frame_uniforms, entity, faces, settings);
        glActiveTexture(GL_TEXTURE0 + kUnitSkin);
        glBindTexture(GL_TEXTURE_2D, skin_texture);
        draw_true_edges(entity, edges, silhouette_mode(plan), plan.creases, settings.edges);
    }
    glBindVertexArray(0);
    glUseProgram(0);
    glActiveTexture(GL_TEXTURE0);
}

}  // namespace nq::npr::technical

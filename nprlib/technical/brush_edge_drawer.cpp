#include "technical/brush_edge_drawer.h"
#include "abi/frame_view.h"
#include "classic/classic_pass.h"

#include <epoxy/gl.h>

#include <algorithm>

#include <glm/gtc/type_ptr.hpp>

namespace nq::npr::technical {
namespace {

constexpr size_t kIndexStreamBytes = size_t{4} << 20;  // per-frame index lists, chunked beyond

constexpr char kVertex[] = R"(#version 330 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec4 a_plane0;
layout(location = 2) in vec4 a_plane1;
layout(location = 3) in vec2 a_edge;  // dihedral angle (degrees), boundary flag
layout(location = 4) in vec3 a_color;
uniform mat4 u_model_view;
out vec3 v_view;
out vec4 v_plane0;
out vec4 v_plane1;
out vec2 v_edge;
out vec3 v_color;
void main() {
    v_view = (u_model_view * vec4(a_position, 1.0)).xyz;
    v_plane0 = a_plane0;
    v_plane1 = a_plane1;
    v_edge = a_edge;
    v_color = a_color;
    gl_Position = vec4(v_view, 1.0);
}
)";

// edge_glsl's library goes between the header and the body.
constexpr char kGeometryHeader[] = R"(#version 330 core
layout(lines) in;
layout(triangle_strip, max_vertices = 4) out;
)";

constexpr char kGeometryBody[] = R"(
in vec3 v_view[];
in vec4 v_plane0[];
in vec4 v_plane1[];
in vec2 v_edge[];
in vec3 v_color[];
uniform vec3 u_eye_model;
uniform int u_silhouettes;
uniform int u_creases;
uniform int u_boundaries;
uniform float u_crease_degrees;

bool faces_eye(vec4 plane) {
    return dot(plane.xyz, u_eye_model) > plane.w;
}

// EDGE_* kind of this edge from this eye, or -1: no line.
int edge_kind() {
    bool front0 = faces_eye(v_plane0[0]);
    if (v_edge[0].y > 0.5) {
        return u_boundaries != 0 && u_silhouettes != 0 && front0 ? EDGE_SILHOUETTE : -1;
    }
    bool front1 = faces_eye(v_plane1[0]);
    if (front0 != front1) return u_silhouettes != 0 ? EDGE_SILHOUETTE : -1;
    float dihedral = v_edge[0].x;
    if (!front0 || u_creases == 0 || abs(dihedral) <= u_crease_degrees) return -1;
    return dihedral > 0.0 ? EDGE_RIDGE : EDGE_VALLEY;
}

void main() {
    int kind = edge_kind();
    if (kind < 0) return;
    vec3 color0 = edge_color(kind, v_color[0], length(v_view[0]));
    vec3 color1 = edge_color(kind, v_color[1], length(v_view[1]));
    emit_edge(v_view[0], v_view[1], color0, color1, kind);
}
)";

bool wants_edges(const EdgeSettings& settings) {
    return settings.world_edges && (settings.silhouettes || settings.creases);
}

}  // namespace

bool BrushEdgeDrawer::init(gl::ObjectTracker* tracker, std::string& error) {
    const std::string geometry =
        std::string(kGeometryHeader) + kEdgeLibrary + kEdgeGeometryLibrary + kGeometryBody;
    gl::ProgramBuild build = gl::Program::build(
        {"technical brush edges", kVertex, kEdgeFragment, geometry.c_str()}, tracker);
    if (!build.ok()) {
        error = build.error;
        return false;
    }
    program_ = std::move(build.program);
    if (!indices_.create(tracker, kIndexStreamBytes)) {
        error = "technical brush edges: cannot create the index stream buffer";
        program_.reset();
        return false;
    }
    return true;
}

void BrushEdgeDrawer::reset() {
    indices_.reset();
    program_.reset();
}

void BrushEdgeDrawer::begin(const npr::FrameView& view, const EdgeFrameUniforms& frame_uniforms,
                            const Placement& placement, const BrushEdgeMesh& mesh,
                            const EdgeSettings& settings) {
    classic::begin_classic_pass();
    program_.use();
    set_edge_uniforms(program_, settings, frame_uniforms);
    const glm::mat4 model_view = view.view * placement.model;
    glUniformMatrix4fv(program_.location("u_model_view"), 1, GL_FALSE, glm::value_ptr(model_view));
    glUniform3fv(program_.location("u_eye_model"), 1, glm::value_ptr(placement.eye_model));
    glUniform1i(program_.location("u_silhouettes"), settings.silhouettes ? 1 : 0);
    glUniform1i(program_.location("u_creases"), settings.creases ? 1 : 0);
    glUniform1i(program_.location("u_boundaries"), placement.boundaries ? 1 : 0);
    glUniform1f(program_.location("u_crease_degrees"), settings.crease_angle_degrees);
    glBindVertexArray(mesh.vertex_array());
}

void BrushEdgeDrawer::draw_indexed(std::span<const uint32_t> line_indices) {
    // Whole lines per push; a list longer than one push is drawn in several.
    const size_t per_push = (indices_.max_push() / sizeof(uint32_t)) & ~size_t{1};
    for (size_t first = 0; first < line_indices.size(); first += per_push) {
        const size_t count = std::min(per_push, line_indices.size() - first);
        const size_t offset =
            indices_.push(line_indices.data() + first, count * sizeof(uint32_t), 4);
        if (offset == gl::StreamBuffer::kNoSpace) return;
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices_.id());
        glDrawElements(GL_LINES, static_cast<GLsizei>(count), GL_UNSIGNED_INT,
                       reinterpret_cast<const void*>(offset));
    }
}

void BrushEdgeDrawer::end() {
    classic::end_classic_pass();
}

void BrushEdgeDrawer::draw_world(const npr::FrameView& view,
                                 const EdgeFrameUniforms& frame_uniforms, const nqr_frame& frame,
                                 const BrushEdgeMesh& mesh, const EdgeSettings& settings) {
    if (!program_ || !wants_edges(settings) || mesh.num_edges() == 0) return;
    const Placement placement{glm::mat4(1.0f), view.eye, false};
    if (!frame.visible_surfaces) {
        begin(view, frame_uniforms, placement, mesh, settings);
        glDrawArrays(GL_LINES, 0, static_cast<GLsizei>(mesh.num_edges() * 2));
        end();
        return;
    }
    const std::span<const uint32_t> lines =
        mesh.line_indices_of({frame.visible_surfaces, frame.num_visible_surfaces});
    if (lines.empty()) return;
    begin(view, frame_uniforms, placement, mesh, settings);
    draw_indexed(lines);
    end();
}

void BrushEdgeDrawer::draw_entity(const npr::FrameView& view,
                                  const EdgeFrameUniforms& frame_uniforms, const nqr_entity& entity,
                                  const BrushEdgeMesh& mesh, uint32_t first_surface,
                                  uint32_t num_surfaces, const EdgeSettings& settings) {
    if (!program_ || !wants_edges(settings)) return;
    const uint32_t first_edge = mesh.table().range_begin(first_surface);
    const uint32_t end_edge = mesh.table().range_end(first_surface, num_surfaces);
    if (end_edge <= first_edge) return;
    const Placement placement{npr::mat4_from(entity.model_matrix), glm::make_vec3(entity.eye_model),
                              true};
    begin(view, frame_uniforms, placement, mesh, settings);
    glDrawArrays(GL_LINES, static_cast<GLint>(first_edge * 2),
                 static_cast<GLsizei>((end_edge - first_edge) * 2));
    end();
}

}  // namespace nq::npr::technical

#include "technical/shadow_drawer.h"

#include <epoxy/gl.h>

#include <algorithm>

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>

#include "abi/abi_access.h"
#include "abi/frame_view.h"

namespace nq::npr::technical {
namespace {

constexpr char kVertex[] = R"(#version 330 core
layout(location = 0) in vec4 a_clip;
layout(location = 1) in float a_alpha;
out float v_alpha;
void main() {
    v_alpha = a_alpha;
    gl_Position = a_clip;
}
)";

constexpr char kFragment[] = R"(#version 330 core
in float v_alpha;
uniform vec3 u_color;
layout(location = 0) out vec4 o_color;
void main() {
    o_color = vec4(u_color, v_alpha);
}
)";

// Shadow and floor share their depth; this pulls the shadow just in front (slope-aware).
constexpr float kOffsetFactor = -1.0f;
constexpr float kOffsetUnits = -2.0f;
constexpr size_t kStreamBytes = size_t{16} << 20;

void begin_shadow_state(bool clear_stencil) {
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_FALSE);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(kOffsetFactor, kOffsetUnits);
    glEnable(GL_STENCIL_TEST);
    glStencilMask(0xFF);
    if (clear_stencil) {
        glClearStencil(0);
        glClear(GL_STENCIL_BUFFER_BIT);
    }
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glColorMaski(1, GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
}

void end_shadow_state() {
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
}

}  // namespace

bool ShadowDrawer::init(gl::ObjectTracker* tracker, std::string& error) {
    reset();
    gl::ProgramBuild build = gl::Program::build({"technical shadow", kVertex, kFragment}, tracker);
    if (!build.ok()) {
        error = build.error;
        return false;
    }
    program_ = std::move(build.program);
    if (!vertex_stream_.create(tracker, kStreamBytes) ||
        !index_stream_.create(tracker, kStreamBytes / 2)) {
        error = "technical shadows: cannot create the shadow stream buffers";
        return false;
    }
    vertex_array_ = gl::VertexArray::create(tracker);
    glBindVertexArray(vertex_array_.id());
    glEnableVertexAttribArray(0);
    glEnableVertexAttribArray(1);
    glBindVertexArray(0);
    vertices_.reserve(8192);
    for (auto& kind : indices_) kind.reserve(8192);
    return true;
}

void ShadowDrawer::reset() {
    stencil_framebuffer_ = -1;
    vertex_array_.reset();
    index_stream_.reset();
    vertex_stream_.reset();
    program_.reset();
    begin_frame();
}

void ShadowDrawer::begin_frame() {
    vertices_.clear();
    for (auto& kind : indices_) kind.clear();
}

size_t ShadowDrawer::triangles_in_batch() const {
    size_t n = 0;
    for (const auto& kind : indices_) n += kind.size() / 3;
    return n;
}

void ShadowDrawer::add_entity(const npr::FrameView& view, const nqr_entity& entity,
                              const AliasEdgeMesh& mesh, const glm::vec3* pose,
                              const ShadowPasses& passes) {
    if (!pose || passes.count <= 0 || !npr::has_known_prefix(&entity)) return;
    const glm::mat4 model = npr::mat4_from(entity.model_matrix);
    // Facing in model space: n_world . l = n_model . (M^-1 l) for the model's linear part.
    const glm::vec3 light = glm::inverse(glm::mat3(model)) * passes.light;
    lit_.clear();
    const std::span<const AliasEdgeMesh::Triangle> triangles = mesh.shadow_triangles();
    for (uint32_t t = 0; t < triangles.size(); ++t) {
        const auto& [a, b, c] = triangles[t];
        const glm::vec3 normal = glm::cross(pose[b] - pose[a], pose[c] - pose[a]);
        if (glm::dot(normal, light) > 0.0f) lit_.push_back(t);
    }
    if (lit_.empty()) return;
    const int count = std::min(passes.count, kKinds);
    for (int p = 0; p < count; ++p) {
        const ShadowPass& pass = passes.pass[p];
        const glm::mat4 to_clip = view.view_projection * pass.world_to_plane * model;
        const auto base = static_cast<uint32_t>(vertices_.size());
        for (uint32_t v = 0; v < mesh.vertex_count(); ++v) {
            vertices_.push_back({to_clip * glm::vec4(pose[v], 1.0f), pass.alpha});
        }
        std::vector<uint32_t>& out = indices_[p];
        for (uint32_t t : lit_) {
            for (uint32_t v : triangles[t]) out.push_back(base + v);
        }
    }
}

// A stencil-only clear of a packed depth-stencil buffer rewrites every depth texel around it;
// instead each frame marks with values of its own (kKinds of them) and the buffer is cleared
// only when they run out (every 85 frames) or the framebuffer changes. True: clear now.
bool ShadowDrawer::next_stencil_values() {
    GLint framebuffer = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer);
    stencil_base_ += kKinds;
    if (stencil_base_ + kKinds <= 255 && framebuffer == stencil_framebuffer_) return false;
    stencil_base_ = 0;
    stencil_framebuffer_ = framebuffer;
    return true;
}

void ShadowDrawer::draw(const ShadowSettings& settings) {
    if (!program_ || vertices_.empty()) return;
    // What one push cannot hold is left out (a million shadow vertices in one frame).
    const size_t bytes = vertices_.size() * sizeof(Vertex);
    if (bytes > vertex_stream_.max_push()) return;
    const size_t offset = vertex_stream_.push(vertices_.data(), bytes, 4);
    if (offset == gl::StreamBuffer::kNoSpace) return;
    program_.use();
    glUniform3f(program_.location("u_color"), settings.color.r, settings.color.g, settings.color.b);
    glBindVertexArray(vertex_array_.id());
    glBindBuffer(GL_ARRAY_BUFFER, vertex_stream_.id());
    const auto at = [offset](size_t field) {
        return reinterpret_cast<const void*>(offset + field);
    };
    glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, sizeof(Vertex), at(offsetof(Vertex, clip)));
    glVertexAttribPointer(1, 1, GL_FLOAT, GL_FALSE, sizeof(Vertex), at(offsetof(Vertex, alpha)));
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    begin_shadow_state(next_stencil_values());
    for (int kind = 0; kind < kKinds; ++kind) {
        const std::vector<uint32_t>& indices = indices_[kind];
        const size_t count =
            std::min(indices.size(), index_stream_.max_push() / sizeof(uint32_t)) / 3 * 3;
        if (count == 0) continue;
        const size_t index_offset = index_stream_.push(indices.data(), count * sizeof(uint32_t), 4);
        if (index_offset == gl::StreamBuffer::kNoSpace) continue;
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, index_stream_.id());
        glStencilFunc(GL_NOTEQUAL, stencil_base_ + kind + 1, 0xFF);
        glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(count), GL_UNSIGNED_INT,
                       reinterpret_cast<const void*>(index_offset));
    }
    end_shadow_state();
}

}  // namespace nq::npr::technical

#include "technical/alias_edge_drawer.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "abi/abi_access.h"
#include "abi/frame_view.h"
#include "technical/alias_pose.h"
#include "technical/shading_model.h"

namespace nq::npr::technical {
namespace {

// The quads, after the edge libraries: each vertex carries both ends of its edge.
constexpr char kQuadBody[] = R"(
layout(location = 0) in vec4 a_own;     // this end (view space), its distance from the eye
layout(location = 1) in vec3 a_other;   // the other end (view space)
layout(location = 2) in vec4 a_shaded;  // the colour shaded here; alpha: side | kind << 1
void main() {
    int side_and_kind = int(a_shaded.a * 255.0 + 0.5);
    int kind = side_and_kind >> 1;
    g_color = edge_color(kind, a_shaded.rgb, a_own.w);
    gl_Position = edge_corner_at(a_own.xyz, a_other, kind, side_and_kind & 1);
}
)";

// Quad corners: 16 MB of ring, 4 MB (130k corners) a push.
constexpr size_t kStreamBytes = size_t{16} << 20;

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

uint8_t unorm8(float value) {
    return static_cast<uint8_t>(std::clamp(value, 0.0f, 1.0f) * 255.0f + 0.5f);
}

}  // namespace

ChainTolerance chain_tolerance(const EdgeFrameUniforms& frame, const EdgeSettings& settings) {
    ChainTolerance out;
    out.pixels = settings.merge_pixels;
    const float scale = frame.projection[1][1] * frame.viewport.y;
    out.units_per_pixel_per_depth = scale > 0.0f ? 2.0f / scale : 0.0f;
    return out;
}

// Shades one entity's edge ends: view position, distance and technical tone per MDL vertex.
class AliasEdgeDrawer::EndShader {
  public:
    EndShader(const npr::FrameView& view, const ShadingSettings& shading, const nqr_entity& entity,
              const classic::AliasModelGpu& faces, const glm::vec3* pose, const SkinSample& skin)
        : shading_(shading),
          skin_(skin),
          pose_(pose),
          st_(faces.model().st),
          normals_(faces.model(), faces.pose_texels(), entity),
          light_(tone_light(entity)) {
        const glm::mat4 model = npr::mat4_from(entity.model_matrix);
        model_view_ = view.view * model;
        normal_to_world_ = glm::inverseTranspose(glm::mat3(model));
    }

    glm::vec3 view_position(uint32_t v) const {
        return glm::vec3(model_view_ * glm::vec4(pose_[v], 1.0f));
    }

    std::array<uint8_t, 3> colour(uint32_t v) const {
        const glm::vec3 c = technical_shade(shading_, light_, kd(v), world_normal(v), pose_[v].z);
        return {unorm8(c.r), unorm8(c.g), unorm8(c.b)};
    }

  private:
    glm::vec3 world_normal(uint32_t v) const {
        if (!normals_.valid()) return {0.0f, 0.0f, 1.0f};
        const glm::vec3 n = normal_to_world_ * normals_.at(v);
        const float len = glm::length(n);
        return len > 1e-6f ? n / len : glm::vec3(0.0f, 0.0f, 1.0f);
    }

    glm::vec3 kd(uint32_t v) const {
        const int32_t* st = st_ + size_t(v) * 3;  // on-seam flag, s, t: the front side
        return skin_.kd(st[1], st[2], shading_.texture_blend);
    }

    const ShadingSettings& shading_;
    const SkinSample& skin_;
    const glm::vec3* pose_;
    const int32_t* st_;
    PoseNormals normals_;
    ToneLight light_;
    glm::mat4 model_view_;
    glm::mat3 normal_to_world_;
};

bool AliasEdgeDrawer::init(gl::ObjectTracker* tracker, std::string& error) {
    reset();
    const std::string quads =
        std::string("#version 330 core\n") + kEdgeLibrary + kEdgeVertexLibrary + kQuadBody;
    gl::ProgramBuild quads_build =
        gl::Program::build({"technical alias edges", quads.c_str(), kEdgeFragment}, tracker);
    if (!quads_build.ok()) {
        error = quads_build.error;
        return false;
    }
    quads_ = std::move(quads_build.program);
    glUseProgram(0);
    if (!corner_stream_.create(tracker, kStreamBytes)) {
        error = "technical alias edges: cannot create the edge stream buffer";
        return false;
    }
    max_edges_ = corner_stream_.max_push() / (4 * sizeof(Corner));

    const std::vector<uint32_t> indices = quad_pattern(max_edges_);
    quad_indices_ = gl::Buffer::create(tracker);
    quads_array_ = gl::VertexArray::create(tracker);
    glBindVertexArray(quads_array_.id());
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, quad_indices_.id());
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indices.size() * 4),
                 indices.data(), GL_STATIC_DRAW);
    for (GLuint attribute = 0; attribute < 3; ++attribute) {
        glEnableVertexAttribArray(attribute);  // pointed at each frame's corners by upload()
    }
    glBindVertexArray(0);
    corners_.reserve(4096);
    found_.reserve(1024);
    return true;
}

void AliasEdgeDrawer::reset() {
    quads_array_.reset();
    quad_indices_.reset();
    corner_stream_.reset();
    quads_.reset();
    clear();
}

void AliasEdgeDrawer::clear() {
    corners_.clear();
    uploaded_ = false;
}

void AliasEdgeDrawer::begin_frame(const npr::FrameView& view, const ShadingSettings& shading,
                                  const ChainTolerance& chains) {
    clear();
    view_ = view;
    shading_ = shading;
    chain_tolerance_ = chains;
}

// Stamps instead of clearing: a new stamp per entity makes every end unplaced and unshaded.
void AliasEdgeDrawer::new_entity_stamp(uint32_t vertex_count) {
    if (end_views_.size() < vertex_count) {
        end_views_.resize(vertex_count);
        shaded_ends_.resize(vertex_count);
        view_stamps_.resize(vertex_count, 0);
        colour_stamps_.resize(vertex_count, 0);
    }
    if (++stamp_ == 0) {
        std::fill(view_stamps_.begin(), view_stamps_.end(), 0);
        std::fill(colour_stamps_.begin(), colour_stamps_.end(), 0);
        stamp_ = 1;
    }
}

EdgeSpan AliasEdgeDrawer::add_entity(const nqr_entity& entity, const classic::AliasModelGpu& faces,
                                     const AliasEdgeMesh& mesh, const glm::vec3* pose,
                                     const SkinSample& skin, const EdgeSettings& settings) {
    EdgeSpan span{corners_.size() / 4, 0};
    const EdgeQuery query = plan_edge_query(mesh, settings);
    if (!query.any() || !pose || uploaded_ || faces.model().num_vertices != mesh.vertex_count()) {
        return span;
    }
    found_.clear();
    mesh.find_edges(pose, glm::make_vec3(entity.eye_model), query, found_);
    if (found_.empty()) return span;
    new_entity_stamp(mesh.vertex_count());
    const EndShader shader(view_, shading_, entity, faces, pose, skin);
    place_ends(shader);
    chains_.simplify(found_, mesh.seam_representatives(), end_views_.data(), chain_tolerance_);
    // What one push cannot hold is left out (tens of thousands of edges in one frame).
    const size_t room = max_edges_ - std::min(max_edges_, span.first_edge);
    span.edge_count = std::min(found_.size(), room);
    append_quads(shader, span.edge_count);
    return span;
}

void AliasEdgeDrawer::place_ends(const EndShader& shader) {
    for (const FoundEdge& e : found_) {
        for (const uint32_t v : {e.v0, e.v1}) {
            if (view_stamps_[v] == stamp_) continue;
            end_views_[v] = shader.view_position(v);
            view_stamps_[v] = stamp_;
        }
    }
}

// The corners of the first `count` edges, written in place: two per end, each end's distance
// and colour worked out once however many edges meet there.
void AliasEdgeDrawer::append_quads(const EndShader& shader, size_t count) {
    const auto shade_end = [&](uint32_t v) {
        if (colour_stamps_[v] == stamp_) return;
        const std::array<uint8_t, 3> c = shader.colour(v);
        // The view transform is rigid: the distance from the eye is the view-space length.
        shaded_ends_[v] = {{c[0], c[1], c[2]}, glm::length(end_views_[v])};
        colour_stamps_[v] = stamp_;
    };
    const size_t first = corners_.size();
    corners_.resize(first + 4 * count);
    Corner* out = corners_.data() + first;
    for (size_t i = 0; i < count; ++i) {
        const FoundEdge& e = found_[i];
        shade_end(e.v0);
        shade_end(e.v1);
        const uint8_t kind = static_cast<uint8_t>(static_cast<uint32_t>(e.kind) << 1);
        const auto corner = [&](uint32_t own, uint32_t other, uint8_t side) {
            const ShadedEnd& end = shaded_ends_[own];
            *out++ = {end_views_[own],
                      end.distance,
                      end_views_[other],
                      {end.rgb[0], end.rgb[1], end.rgb[2]},
                      static_cast<uint8_t>(kind | side)};
        };
        corner(e.v0, e.v1, 0);
        corner(e.v0, e.v1, 1);
        // Seen from the far end the sides swap: (v1, 0) lies beside (v0, 1).
        corner(e.v1, e.v0, 0);
        corner(e.v1, e.v0, 1);
    }
}

void AliasEdgeDrawer::upload() {
    uploaded_ = true;
    if (corners_.empty()) return;
    const size_t offset = corner_stream_.push(corners_.data(), corners_.size() * sizeof(Corner), 4);
    if (offset == gl::StreamBuffer::kNoSpace) {
        corners_.clear();  // cannot happen: add_entity caps the batch
        return;
    }
    glBindVertexArray(quads_array_.id());
    glBindBuffer(GL_ARRAY_BUFFER, corner_stream_.id());
    glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, sizeof(Corner), at(offset));
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(Corner),
                          at(offset + offsetof(Corner, other)));
    glVertexAttribPointer(2, 4, GL_UNSIGNED_BYTE, GL_TRUE, sizeof(Corner),
                          at(offset + offsetof(Corner, shaded)));
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glBindVertexArray(0);
}

void AliasEdgeDrawer::begin(const EdgeFrameUniforms& frame_uniforms, const EdgeSettings& settings) {
    quads_.use();
    set_edge_uniforms(quads_, settings, frame_uniforms);
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
}

void AliasEdgeDrawer::draw_entity(const npr::FrameView& view,
                                  const EdgeFrameUniforms& frame_uniforms, const nqr_entity& entity,
                                  const classic::AliasModelGpu& faces, const AliasEdgeMesh& edges,
                                  const SkinSample& skin, const TechnicalSettings& settings) {
    if (!quads_ || !npr::has_known_prefix(&entity)) return;
    pose_.resize(edges.vertex_count());
    blend_alias_pose(faces.model(), entity, pose_.data());
    begin_frame(view, settings.shading, chain_tolerance(frame_uniforms, settings.edges));
    const EdgeSpan span = add_entity(entity, faces, edges, pose_.data(), skin, settings.edges);
    upload();
    begin(frame_uniforms, settings.edges);
    draw(span);
    end();
}

}  // namespace nq::npr::technical

#include "technical/alias_edge_mesh.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

#include "adjacency/model_adjacency.h"
#include "classic/alias_mesh.h"

namespace nq::npr::technical {
namespace {

// Per MDL vertex: its skin coordinate on the front side of the seam.
std::vector<float> front_skin_coords(const nqr_alias_model& model) {
    std::vector<float> uv;
    uv.reserve(static_cast<size_t>(model.num_vertices) * 2);
    for (uint32_t v = 0; v < model.num_vertices; ++v) {
        const int32_t* st = model.st + static_cast<size_t>(v) * 3;
        uv.push_back((static_cast<float>(st[1]) + 0.5f) / static_cast<float>(model.skin_width));
        uv.push_back((static_cast<float>(st[2]) + 0.5f) / static_cast<float>(model.skin_height));
    }
    return uv;
}

bool usable_triangle(const nqr_alias_model& model, const int32_t* corners) {
    for (int k = 0; k < 3; ++k) {
        if (corners[k] < 0 || static_cast<uint32_t>(corners[k]) >= model.num_vertices) {
            return false;
        }
    }
    return corners[0] != corners[1] && corners[1] != corners[2] && corners[2] != corners[0];
}

// The file's triangles (clockwise seen from outside), appended counter-clockwise.
void append_file_triangles(const nqr_alias_model& model, std::vector<uint32_t>& indices) {
    for (uint32_t t = 0; t < model.num_triangles; ++t) {
        const int32_t* corners = model.triangles + static_cast<size_t>(t) * 4 + 1;
        if (!usable_triangle(model, corners)) continue;
        indices.insert(indices.end(),
                       {static_cast<uint32_t>(corners[0]), static_cast<uint32_t>(corners[2]),
                        static_cast<uint32_t>(corners[1])});
    }
}

// One GL_LINES_ADJACENCY primitive per mesh edge, in MDL indices: (third corner of face0, v0,
// v1, far corner of the neighbour), from face0's slice of triangles_adjacency. On an open
// border the "far corner" is face0's own third corner, which the shader recognises.
void append_edge_lines_adjacency(const adjacency::EdgeTable& table,
                                 std::vector<uint32_t>& indices) {
    for (uint32_t e = 0; e < table.edges.size(); ++e) {
        const uint32_t face = table.edges[e].face0;
        const auto& sides = table.face_edges[face];
        const uint32_t* corners = table.triangles_adjacency.data() + size_t(face) * 6;
        for (uint32_t k = 0; k < 3; ++k) {
            if (sides[k] != e) continue;
            indices.insert(indices.end(), {corners[2 * ((k + 2) % 3)], corners[2 * k],
                                           corners[2 * ((k + 1) % 3)], corners[2 * k + 1]});
            break;
        }
    }
}

}  // namespace

std::unique_ptr<AliasEdgeMesh> AliasEdgeMesh::create(gl::ObjectTracker* tracker,
                                                     const nqr_alias_model& model,
                                                     std::string& error) {
    if (!classic::validate_alias_model(model, error)) return nullptr;
    adjacency::ModelAdjacency recovered = adjacency::recover_adjacency(model);
    std::unique_ptr<AliasEdgeMesh> mesh(new AliasEdgeMesh());
    mesh->stats_ = recovered.stats;
    mesh->verdict_ = std::move(recovered.verdict);

    std::vector<uint32_t> indices = recovered.edges.triangles_adjacency;
    mesh->adjacency_count_ = static_cast<GLsizei>(indices.size());
    append_file_triangles(model, indices);
    mesh->triangle_count_ = static_cast<GLsizei>(indices.size()) - mesh->adjacency_count_;
    append_edge_lines_adjacency(recovered.edges, indices);
    mesh->edge_count_ =
        static_cast<GLsizei>(indices.size()) - mesh->adjacency_count_ - mesh->triangle_count_;
    mesh->model_ = &model;
    mesh->edge_prims_.assign(indices.end() - mesh->edge_count_, indices.end());
    mesh->positions_.resize(model.num_vertices);
    mesh->candidates_.reserve(mesh->edge_prims_.size());
    const std::vector<float> uv = front_skin_coords(model);

    mesh->vertex_array_ = gl::VertexArray::create(tracker);
    mesh->skin_coords_ = gl::Buffer::create(tracker);
    mesh->indices_ = gl::Buffer::create(tracker);
    glBindVertexArray(mesh->vertex_array_.id());
    glBindBuffer(GL_ARRAY_BUFFER, mesh->skin_coords_.id());
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(uv.size() * sizeof(float)), uv.data(),
                 GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(float), nullptr);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, mesh->indices_.id());
    glBufferData(GL_ELEMENT_ARRAY_BUFFER,
                 static_cast<GLsizeiptr>(indices.size() * sizeof(uint32_t)), indices.data(),
                 GL_STATIC_DRAW);
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    return mesh;
}

namespace {

// The entity's pose pair, clamped as set_alias_pose_uniforms clamps it, blended on the CPU.
void blend_pose(const nqr_alias_model& model, const nqr_entity& entity,
                std::vector<glm::vec3>& out) {
    const uint32_t last = model.num_poses - 1;
    const nqr_alias_vertex* pose0 =
        model.poses + size_t(std::min(entity.pose0, last)) * model.num_vertices;
    const nqr_alias_vertex* pose1 =
        model.poses + size_t(std::min(entity.pose1, last)) * model.num_vertices;
    const float t = std::clamp(entity.lerp, 0.0f, 1.0f);
    for (uint32_t v = 0; v < model.num_vertices; ++v) {
        for (int k = 0; k < 3; ++k) {
            const float packed =
                float(pose0[v].v[k]) + (float(pose1[v].v[k]) - float(pose0[v].v[k])) * t;
            out[v][k] = model.scale[k] * packed + model.origin[k];
        }
    }
}

// Facing of a face with normal n through p, seen from eye: +1 front, -1 back, 0 too close to
// call (kept either way).
int facing(const glm::vec3& n, const glm::vec3& p, const glm::vec3& eye) {
    const float d = glm::dot(n, eye - p);
    const float tolerance = 1e-4f * glm::length(n) * glm::length(eye - p);
    return d > tolerance ? 1 : (d < -tolerance ? -1 : 0);
}

}  // namespace

std::span<const uint32_t> AliasEdgeMesh::candidate_edges(const nqr_entity& entity, float cos_crease,
                                                         bool creases) const {
    candidates_.clear();
    if (!model_ || edge_prims_.empty()) return candidates_;
    blend_pose(*model_, entity, positions_);
    const glm::vec3 eye(entity.eye_model[0], entity.eye_model[1], entity.eye_model[2]);
    // A degree of slack on the threshold: the shader's normals are not bit-identical to ours.
    const float crease_limit =
        std::cos(std::max(std::acos(std::clamp(cos_crease, -1.0f, 1.0f)) - 0.0175f, 0.0f));
    for (size_t i = 0; i + 3 < edge_prims_.size(); i += 4) {
        const uint32_t* prim = &edge_prims_[i];
        bool keep = prim[3] == prim[0];  // an open border
        if (!keep) {
            const glm::vec3 &third = positions_[prim[0]], &p0 = positions_[prim[1]];
            const glm::vec3 &p1 = positions_[prim[2]], &far = positions_[prim[3]];
            const glm::vec3 n0 = glm::cross(p1 - p0, third - p0);
            const glm::vec3 n1 = glm::cross(p0 - p1, far - p1);
            const int f0 = facing(n0, p0, eye), f1 = facing(n1, p1, eye);
            keep = f0 != f1 || f0 == 0;  // a silhouette, or too close to call
            if (!keep && creases && f0 > 0) {
                const float l0 = glm::length(n0), l1 = glm::length(n1);
                keep = l0 > 0.0f && l1 > 0.0f && glm::dot(n0, n1) < crease_limit * l0 * l1;
            }
        }
        if (keep) candidates_.insert(candidates_.end(), prim, prim + 4);
    }
    return candidates_;
}

std::string AliasEdgeMesh::verdict_line(const std::string& model_name) const {
    return "adjacency: " + model_name + ": " + adjacency::edge_style_name(verdict_.style) + " (" +
           verdict_.reason + ")";
}

const void* AliasEdgeMesh::edge_indices_offset() const {
    return reinterpret_cast<const void*>(
        static_cast<uintptr_t>(adjacency_count_ + triangle_count_) * sizeof(uint32_t));
}

const void* AliasEdgeMesh::triangle_indices_offset() const {
    return reinterpret_cast<const void*>(static_cast<uintptr_t>(adjacency_count_) *
                                         sizeof(uint32_t));
}

}  // namespace nq::npr::technical

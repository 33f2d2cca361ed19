#include "technical/alias_edge_mesh.h"

#include <epoxy/gl.h>

#include <vector>

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

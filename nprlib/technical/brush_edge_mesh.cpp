#include "technical/brush_edge_mesh.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "abi/abi_access.h"

namespace nq::npr::technical {
namespace {

using npr::abi_element;

constexpr glm::vec3 kNoTextureColor{0.5f};

// The average colour of a texture's smallest mip level present, through the palette.
glm::vec3 texture_average_color(const nqr_texture& texture, const uint8_t* palette_rgb) {
    for (int level = 3; level >= 0; --level) {
        const uint32_t width = texture.width >> level, height = texture.height >> level;
        if (!texture.mips[level] || width == 0 || height == 0) continue;
        glm::vec3 sum(0.0f);
        const size_t count = static_cast<size_t>(width) * height;
        for (size_t i = 0; i < count; ++i) {
            const uint8_t* rgb = palette_rgb + texture.mips[level][i] * 3;
            sum += glm::vec3(rgb[0], rgb[1], rgb[2]);
        }
        return sum / (255.0f * static_cast<float>(count));
    }
    return kNoTextureColor;
}

std::vector<glm::vec3> surface_colors(const nqr_brush_model& brush, const uint8_t* palette_rgb) {
    std::vector<glm::vec3> texture_colors(brush.num_textures, kNoTextureColor);
    for (uint32_t t = 0; palette_rgb && t < brush.num_textures; ++t) {
        texture_colors[t] = texture_average_color(abi_element(brush.textures, t), palette_rgb);
    }
    std::vector<glm::vec3> colors(brush.num_surfaces, kNoTextureColor);
    for (uint32_t s = 0; s < brush.num_surfaces; ++s) {
        const int32_t texture = abi_element(brush.surfaces, s).texture;
        if (texture >= 0 && static_cast<uint32_t>(texture) < brush.num_textures) {
            colors[s] = texture_colors[static_cast<uint32_t>(texture)];
        }
    }
    return colors;
}

void copy_plane(const nqr_surface& surface, float* out) {
    std::copy(surface.normal, surface.normal + 3, out);
    out[3] = surface.dist;
}

uint8_t to_byte(float value) {
    return static_cast<uint8_t>(std::clamp(value, 0.0f, 1.0f) * 255.0f + 0.5f);
}

BrushEdgeVertex edge_vertex(const nqr_brush_model& brush, const BrushEdge& edge,
                            const glm::vec3& position, const glm::vec3& color) {
    BrushEdgeVertex v{};
    v.position[0] = position.x;
    v.position[1] = position.y;
    v.position[2] = position.z;
    copy_plane(abi_element(brush.surfaces, edge.face0), v.plane0);
    copy_plane(abi_element(brush.surfaces, edge.is_boundary() ? edge.face0 : edge.face1), v.plane1);
    v.dihedral_degrees = edge.dihedral_degrees;
    v.boundary = edge.is_boundary() ? 1.0f : 0.0f;
    v.color[0] = to_byte(color.r);
    v.color[1] = to_byte(color.g);
    v.color[2] = to_byte(color.b);
    v.color[3] = 255;
    return v;
}

std::vector<BrushEdgeVertex> edge_vertices(const nqr_brush_model& brush,
                                           const BrushEdgeTable& table,
                                           const uint8_t* palette_rgb) {
    const std::vector<glm::vec3> colors = surface_colors(brush, palette_rgb);
    std::vector<BrushEdgeVertex> vertices;
    vertices.reserve(table.edges().size() * 2);
    for (const BrushEdge& edge : table.edges()) {
        const glm::vec3 color = edge.is_boundary()
                                    ? colors[edge.face0]
                                    : (colors[edge.face0] + colors[edge.face1]) * 0.5f;
        vertices.push_back(edge_vertex(brush, edge, edge.v0, color));
        vertices.push_back(edge_vertex(brush, edge, edge.v1, color));
    }
    return vertices;
}

// Attribute 3 reads the dihedral angle and the boundary flag as one vec2.
static_assert(offsetof(BrushEdgeVertex, boundary) ==
              offsetof(BrushEdgeVertex, dihedral_degrees) + sizeof(float));

void float_attribute(GLuint location, GLint components, size_t offset) {
    glEnableVertexAttribArray(location);
    glVertexAttribPointer(location, components, GL_FLOAT, GL_FALSE, sizeof(BrushEdgeVertex),
                          reinterpret_cast<const void*>(offset));
}

}  // namespace

std::unique_ptr<BrushEdgeMesh> BrushEdgeMesh::create(gl::ObjectTracker* tracker,
                                                     const nqr_brush_model& brush,
                                                     std::string& error,
                                                     const uint8_t* palette_rgb) {
    std::unique_ptr<BrushEdgeMesh> mesh(new BrushEdgeMesh());
    std::string table_error;
    mesh->table_ = BrushEdgeTable::build(brush, table_error);
    if (!table_error.empty()) {
        error = table_error;
        return nullptr;
    }
    mesh->upload(tracker, edge_vertices(brush, mesh->table_, palette_rgb));
    mesh->index_drawable_edges();
    mesh->line_indices_.reserve(mesh->table_.edges().size() * 2);
    mesh->edge_stamps_.assign(mesh->table_.edges().size(), 0);
    return mesh;
}

void BrushEdgeMesh::upload(gl::ObjectTracker* tracker,
                           const std::vector<BrushEdgeVertex>& vertices) {
    vertex_array_ = gl::VertexArray::create(tracker);
    vertices_ = gl::Buffer::create(tracker);
    glBindVertexArray(vertex_array_.id());
    glBindBuffer(GL_ARRAY_BUFFER, vertices_.id());
    glBufferData(GL_ARRAY_BUFFER,
                 static_cast<GLsizeiptr>(vertices.size() * sizeof(BrushEdgeVertex)),
                 vertices.empty() ? nullptr : vertices.data(), GL_STATIC_DRAW);
    float_attribute(0, 3, offsetof(BrushEdgeVertex, position));
    float_attribute(1, 4, offsetof(BrushEdgeVertex, plane0));
    float_attribute(2, 4, offsetof(BrushEdgeVertex, plane1));
    float_attribute(3, 2, offsetof(BrushEdgeVertex, dihedral_degrees));  // with `boundary`
    glEnableVertexAttribArray(4);
    glVertexAttribPointer(4, 3, GL_UNSIGNED_BYTE, GL_TRUE, sizeof(BrushEdgeVertex),
                          reinterpret_cast<const void*>(offsetof(BrushEdgeVertex, color)));
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
}

// Faces meeting at less than this: one plane, up to rounding.
constexpr float kFlatDegrees = 0.01f;

void BrushEdgeMesh::index_drawable_edges() {
    first_drawable_.assign(1, 0);
    for (uint32_t surface = 0; surface < table_.num_surfaces(); ++surface) {
        for (const uint32_t edge : table_.shared_edges_of(surface)) {
            if (std::abs(table_.edges()[edge].dihedral_degrees) >= kFlatDegrees) {
                drawable_edges_.push_back(edge);
            }
        }
        first_drawable_.push_back(static_cast<uint32_t>(drawable_edges_.size()));
    }
}

std::span<const uint32_t> BrushEdgeMesh::line_indices_of(std::span<const uint32_t> surfaces) const {
    if (++stamp_ == 0) {  // wrapped: old stamps could match again
        std::fill(edge_stamps_.begin(), edge_stamps_.end(), 0);
        stamp_ = 1;
    }
    line_indices_.clear();  // keeps the capacity reserved at create
    for (const uint32_t surface : surfaces) {
        if (surface + 1 >= first_drawable_.size()) continue;
        for (uint32_t i = first_drawable_[surface]; i < first_drawable_[surface + 1]; ++i) {
            const uint32_t edge = drawable_edges_[i];
            if (edge_stamps_[edge] == stamp_) continue;
            edge_stamps_[edge] = stamp_;
            line_indices_.push_back(edge * 2);
            line_indices_.push_back(edge * 2 + 1);
        }
    }
    return line_indices_;
}

}  // namespace nq::npr::technical

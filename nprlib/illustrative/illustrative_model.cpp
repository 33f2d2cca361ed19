#include "illustrative/illustrative_model.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <unordered_map>

#include "classic/alias_mesh.h"

namespace nq::npr::illustrative {
namespace {

struct Vertex {
    uint32_t pose_vertex;
    float uv[2];
    uint32_t normal_slot;
};

const int32_t* triangle_at(const nqr_alias_model& model, uint32_t t) {
    return model.triangles + static_cast<size_t>(t) * 4;
}

// Unique (MDL vertex, seam side, slot) corners as vertices, triangles as indices.
void build_mesh(const nqr_alias_model& model, const CornerNormals& normals,
                std::vector<Vertex>& vertices, std::vector<uint32_t>& indices) {
    std::unordered_map<uint64_t, uint32_t> lookup;
    for (uint32_t t = 0; t < model.num_triangles; ++t) {
        const int32_t* triangle = triangle_at(model, t);
        if (!classic::alias_triangle_valid(model, triangle)) continue;
        for (int corner = 1; corner <= 3; ++corner) {
            const auto vertex = static_cast<uint32_t>(triangle[corner]);
            const bool back = classic::alias_vertex_on_back_of_seam(model, triangle, corner);
            const uint32_t slot = normals.corner_slots[static_cast<size_t>(t) * 3 + corner - 1];
            const uint64_t key = (static_cast<uint64_t>(slot) << 33) |
                                 (static_cast<uint64_t>(vertex) << 1) | (back ? 1u : 0u);
            auto [it, added] = lookup.try_emplace(key, static_cast<uint32_t>(vertices.size()));
            if (added) {
                const std::array<float, 2> uv = classic::alias_skin_uv(model, vertex, back);
                vertices.push_back({vertex, {uv[0], uv[1]}, slot});
            }
            indices.push_back(it->second);
        }
    }
}

bool normals_fit(const nqr_alias_model& model, const CornerNormals& normals, std::string& error) {
    if (normals.corner_slots.size() != static_cast<size_t>(model.num_triangles) * 3) {
        error = "illustrative normals: corner count does not match the model's triangles";
    } else if (normals.num_slots == 0 ||
               normals.normals.size() != static_cast<size_t>(model.num_poses) * normals.num_slots) {
        error = "illustrative normals: normal count does not match the model's poses";
    } else if (std::any_of(normals.corner_slots.begin(), normals.corner_slots.end(),
                           [&](uint32_t slot) { return slot >= normals.num_slots; })) {
        error = "illustrative normals: a corner names a slot out of range";
    }
    return error.empty();
}

uint8_t encode_unit(float component) {
    return static_cast<uint8_t>(std::lround(std::clamp(component, -1.0f, 1.0f) * 127.5f + 127.5f));
}

}  // namespace

CornerNormals mdl_vertex_normals(const nqr_alias_model& model) {
    CornerNormals out;
    out.num_slots = model.num_vertices;
    out.corner_slots.resize(static_cast<size_t>(model.num_triangles) * 3, 0);
    for (uint32_t t = 0; t < model.num_triangles; ++t) {
        const int32_t* triangle = triangle_at(model, t);
        if (!classic::alias_triangle_valid(model, triangle)) continue;
        for (int c = 0; c < 3; ++c) {
            out.corner_slots[static_cast<size_t>(t) * 3 + c] = static_cast<uint32_t>(triangle[c + 1]);
        }
    }
    out.normals.reserve(static_cast<size_t>(model.num_poses) * model.num_vertices);
    std::vector<float> pose;
    for (uint32_t p = 0; p < model.num_poses; ++p) {
        classic::compute_pose_normals(model, p, pose);
        for (uint32_t v = 0; v < model.num_vertices; ++v) {
            out.normals.emplace_back(pose[v * 3], pose[v * 3 + 1], pose[v * 3 + 2]);
        }
    }
    return out;
}

std::unique_ptr<IllustrativeModel> IllustrativeModel::create(gl::ObjectTracker* tracker,
                                                             const nqr_alias_model& model,
                                                             const CornerNormals& normals,
                                                             std::string& error) {
    if (!classic::validate_alias_model(model, error) || !normals_fit(model, normals, error)) {
        return nullptr;
    }
    std::unique_ptr<IllustrativeModel> out(new IllustrativeModel());
    if (!out->upload_normals(tracker, normals, error)) return nullptr;
    std::vector<Vertex> vertices;
    std::vector<uint32_t> indices;
    build_mesh(model, normals, vertices, indices);

    out->vertex_array_ = gl::VertexArray::create(tracker);
    out->vertices_ = gl::Buffer::create(tracker);
    out->indices_ = gl::Buffer::create(tracker);
    glBindVertexArray(out->vertex_array_.id());
    glBindBuffer(GL_ARRAY_BUFFER, out->vertices_.id());
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(Vertex)),
                 vertices.data(), GL_STATIC_DRAW);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, out->indices_.id());
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indices.size() * 4),
                 indices.data(), GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribIPointer(0, 1, GL_UNSIGNED_INT, sizeof(Vertex),
                           reinterpret_cast<const void*>(offsetof(Vertex, pose_vertex)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                          reinterpret_cast<const void*>(offsetof(Vertex, uv)));
    glEnableVertexAttribArray(2);
    glVertexAttribIPointer(2, 1, GL_UNSIGNED_INT, sizeof(Vertex),
                           reinterpret_cast<const void*>(offsetof(Vertex, normal_slot)));
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    out->index_count_ = static_cast<GLsizei>(indices.size());

    float low = 255.0f, high = 0.0f;
    const size_t pose_vertices = static_cast<size_t>(model.num_poses) * model.num_vertices;
    for (size_t i = 0; i < pose_vertices; ++i) {
        low = std::min(low, static_cast<float>(model.poses[i].v[2]));
        high = std::max(high, static_cast<float>(model.poses[i].v[2]));
    }
    out->height_min_ = model.scale[2] * low + model.origin[2];
    out->height_max_ = model.scale[2] * std::max(high, low + 1.0f) + model.origin[2];
    return out;
}

bool IllustrativeModel::upload_normals(gl::ObjectTracker* tracker, const CornerNormals& normals,
                                       std::string& error) {
    GLint max_texels = 0;
    glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &max_texels);
    if (normals.normals.size() > static_cast<size_t>(max_texels)) {
        error = "illustrative normals need " + std::to_string(normals.normals.size()) +
                " buffer texels, the GL allows " + std::to_string(max_texels);
        return false;
    }
    std::vector<uint8_t> texels(normals.normals.size() * 4, 255);
    for (size_t i = 0; i < normals.normals.size(); ++i) {
        for (int c = 0; c < 3; ++c) texels[i * 4 + c] = encode_unit(normals.normals[i][c]);
    }
    normal_buffer_ = gl::Buffer::create(tracker);
    glBindBuffer(GL_TEXTURE_BUFFER, normal_buffer_.id());
    glBufferData(GL_TEXTURE_BUFFER, static_cast<GLsizeiptr>(texels.size()), texels.data(),
                 GL_STATIC_DRAW);
    glBindBuffer(GL_TEXTURE_BUFFER, 0);
    normal_texture_ = gl::Texture::create(tracker);
    glBindTexture(GL_TEXTURE_BUFFER, normal_texture_.id());
    glTexBuffer(GL_TEXTURE_BUFFER, GL_RGBA8, normal_buffer_.id());
    glBindTexture(GL_TEXTURE_BUFFER, 0);
    normal_slots_ = normals.num_slots;
    return true;
}

}  // namespace nq::npr::illustrative

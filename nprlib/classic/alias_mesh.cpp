#include "classic/alias_mesh.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "abi/abi_access.h"

namespace nq::npr::classic {
namespace {

void pose_position(const nqr_alias_model& model, const nqr_alias_vertex& v, float* out) {
    for (int i = 0; i < 3; ++i) out[i] = model.scale[i] * v.v[i] + model.origin[i];
}

// Index of the mesh vertex for (vertex, back-of-seam), made on first use.
uint32_t mesh_vertex(const nqr_alias_model& model, uint32_t vertex, bool back_of_seam,
                     std::vector<int64_t>& lookup, AliasMesh& mesh) {
    const size_t key = static_cast<size_t>(vertex) * 2 + (back_of_seam ? 1 : 0);
    if (lookup[key] >= 0) return static_cast<uint32_t>(lookup[key]);
    const std::array<float, 2> uv = alias_skin_uv(model, vertex, back_of_seam);
    AliasMeshVertex out{vertex, {uv[0], uv[1]}};
    lookup[key] = static_cast<int64_t>(mesh.vertices.size());
    mesh.vertices.push_back(out);
    return static_cast<uint32_t>(lookup[key]);
}

void pack_poses(const nqr_alias_model& model, AliasMesh& mesh) {
    const size_t per_pose = static_cast<size_t>(model.num_vertices) * kPoseTexelsPerVertex * 4;
    mesh.pose_texels.assign(per_pose * model.num_poses, 0);
    std::vector<float> normals;
    for (uint32_t pose = 0; pose < model.num_poses; ++pose) {
        compute_pose_normals(model, pose, normals);
        uint8_t* out = mesh.pose_texels.data() + per_pose * pose;
        const nqr_alias_vertex* vertices =
            model.poses + static_cast<size_t>(pose) * model.num_vertices;
        for (uint32_t v = 0; v < model.num_vertices; ++v, out += 8) {
            for (int i = 0; i < 3; ++i) {
                out[i] = vertices[v].v[i];
                out[4 + i] = encode_normal_component(normals[v * 3 + i]);
            }
        }
    }
}

}  // namespace

bool alias_triangle_valid(const nqr_alias_model& model, const int32_t* triangle) {
    for (int corner = 1; corner <= 3; ++corner) {
        if (triangle[corner] < 0 || static_cast<uint32_t>(triangle[corner]) >= model.num_vertices) {
            return false;
        }
    }
    return true;
}

bool alias_vertex_on_back_of_seam(const nqr_alias_model& model, const int32_t* triangle,
                                  int corner) {
    const bool faces_front = triangle[0] != 0;
    const auto vertex = static_cast<size_t>(triangle[corner]);
    return !faces_front && model.st[vertex * 3] != 0;
}

std::array<float, 2> alias_skin_uv(const nqr_alias_model& model, uint32_t vertex,
                                   bool back_of_seam) {
    const int32_t* st = model.st + static_cast<size_t>(vertex) * 3;
    float s = static_cast<float>(st[1]);
    if (back_of_seam) s += static_cast<float>(model.skin_width / 2);
    return {(s + 0.5f) / static_cast<float>(model.skin_width),
            (static_cast<float>(st[2]) + 0.5f) / static_cast<float>(model.skin_height)};
}

bool validate_alias_model(const nqr_alias_model& model, std::string& error) {
    if (!has_known_prefix(&model)) {
        error = "alias model struct is smaller than this nprlib expects";
    } else if (model.skin_width <= 0 || model.skin_height <= 0) {
        error = "alias model has an empty skin size";
    } else if (model.num_vertices == 0 || model.num_triangles == 0 || model.num_poses == 0) {
        error = "alias model has no vertices, triangles or poses";
    } else if (!model.st || !model.triangles || !model.poses) {
        error = "alias model lacks st, triangle or pose data";
    } else if (!abi_array_usable(model.skins, model.num_skins)) {
        error = "alias model skins of an unknown size";
    }
    return error.empty();
}

uint8_t encode_normal_component(float value) {
    return static_cast<uint8_t>(std::lround(std::clamp(value, -1.0f, 1.0f) * 127.5f + 127.5f));
}

float decode_normal_component(uint8_t value) {
    return (static_cast<float>(value) - 127.5f) / 127.5f;
}

namespace {

using Vec3 = std::array<float, 3>;

Vec3 sub(const Vec3& a, const Vec3& b) {
    return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
float dot(const Vec3& a, const Vec3& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
float length(const Vec3& a) {
    return std::sqrt(dot(a, a));
}

// Angle at corner `a` of triangle (a, b, c).
float corner_angle(const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 u = sub(b, a), v = sub(c, a);
    const float lengths = length(u) * length(v);
    if (lengths <= 0.0f) return 0.0f;
    return std::acos(std::clamp(dot(u, v) / lengths, -1.0f, 1.0f));
}

}  // namespace

void compute_pose_normals(const nqr_alias_model& model, uint32_t pose, std::vector<float>& out) {
    out.assign(static_cast<size_t>(model.num_vertices) * 3, 0.0f);
    const nqr_alias_vertex* vertices = model.poses + static_cast<size_t>(pose) * model.num_vertices;
    for (uint32_t t = 0; t < model.num_triangles; ++t) {
        const int32_t* triangle = model.triangles + static_cast<size_t>(t) * 4;
        if (!alias_triangle_valid(model, triangle)) continue;
        Vec3 p[3];
        for (int c = 0; c < 3; ++c) pose_position(model, vertices[triangle[c + 1]], p[c].data());
        // Quake's triangles wind clockwise seen from outside, so (p2 - p0) x (p1 - p0) points
        // outward. Each face adds its unit normal weighted by its angle at the vertex (so a
        // face's weight does not depend on how it was split into triangles).
        Vec3 n = cross(sub(p[2], p[0]), sub(p[1], p[0]));
        const float n_length = length(n);
        if (n_length <= 0.0f) continue;
        for (float& component : n) component /= n_length;
        for (int c = 0; c < 3; ++c) {
            const float angle = corner_angle(p[c], p[(c + 1) % 3], p[(c + 2) % 3]);
            float* accumulated = &out[static_cast<size_t>(triangle[c + 1]) * 3];
            for (int i = 0; i < 3; ++i) accumulated[i] += n[i] * angle;
        }
    }
    for (uint32_t v = 0; v < model.num_vertices; ++v) {
        float* n = &out[static_cast<size_t>(v) * 3];
        const float len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        if (len > 1e-12f) {
            for (int i = 0; i < 3; ++i) n[i] /= len;
        } else {
            n[0] = n[1] = 0.0f;
            n[2] = 1.0f;  // isolated or degenerate: face up
        }
    }
}

AliasMesh build_alias_mesh(const nqr_alias_model& model) {
    AliasMesh mesh;
    std::vector<int64_t> lookup(static_cast<size_t>(model.num_vertices) * 2, -1);
    for (uint32_t t = 0; t < model.num_triangles; ++t) {
        const int32_t* triangle = model.triangles + static_cast<size_t>(t) * 4;
        if (!alias_triangle_valid(model, triangle)) continue;
        for (int corner = 1; corner <= 3; ++corner) {
            const auto vertex = static_cast<uint32_t>(triangle[corner]);
            mesh.indices.push_back(
                mesh_vertex(model, vertex, alias_vertex_on_back_of_seam(model, triangle, corner),
                            lookup, mesh));
        }
    }
    pack_poses(model, mesh);
    return mesh;
}

}  // namespace nq::npr::classic

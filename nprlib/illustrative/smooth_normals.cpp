#include "illustrative/smooth_normals.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "adjacency/alias_source.h"
#include "adjacency/weld.h"

namespace nq::npr::illustrative {
namespace {

constexpr uint32_t kNone = SmoothingLayout::kNoGroup;

// Outward unit normal of a clockwise (Quake) triangle, or zero when it has no area.
glm::vec3 face_normal(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2) {
    const glm::vec3 n = glm::cross(p2 - p0, p1 - p0);
    const float length = glm::length(n);
    if (!(length > 1e-12f) || !std::isfinite(length)) return glm::vec3(0.0f);
    return n / length;
}

// Angle at corner a of triangle (a, b, c); 0 when an edge has no length.
float corner_angle(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    const glm::vec3 u = b - a, v = c - a;
    const float lengths = glm::length(u) * glm::length(v);
    if (!(lengths > 0.0f)) return 0.0f;
    return std::acos(std::clamp(glm::dot(u, v) / lengths, -1.0f, 1.0f));
}

std::string check_mesh(const SmoothingMesh& mesh) {
    if (mesh.indices.size() % 3 != 0) return "index count is not a multiple of 3";
    for (uint32_t d : mesh.indices) {
        if (d >= mesh.vertex_position.size()) return "a corner names a missing drawn vertex";
    }
    for (uint32_t p : mesh.vertex_position) {
        if (p >= mesh.position_weld.size()) return "a drawn vertex names a missing position";
    }
    for (uint32_t w : mesh.position_weld) {
        if (w >= mesh.position_weld.size()) return "a position names a missing welded vertex";
    }
    return {};
}

uint32_t weld_of_corner(const SmoothingMesh& mesh, size_t corner) {
    return mesh.position_weld[mesh.vertex_position[mesh.indices[corner]]];
}

glm::vec3 corner_position(const SmoothingMesh& mesh, std::span<const glm::vec3> positions,
                          size_t corner) {
    return positions[mesh.vertex_position[mesh.indices[corner]]];
}

// Per triangle and pose: its outward normal (zero when degenerate in that pose).
std::vector<glm::vec3> face_normals(const SmoothingMesh& mesh, std::span<const glm::vec3> poses,
                                    uint32_t num_poses) {
    const size_t triangles = mesh.indices.size() / 3;
    std::vector<glm::vec3> out(triangles * num_poses);
    for (uint32_t pose = 0; pose < num_poses; ++pose) {
        const auto positions =
            poses.subspan(size_t(pose) * mesh.num_positions(), mesh.num_positions());
        for (size_t t = 0; t < triangles; ++t) {
            out[t * num_poses + pose] = face_normal(corner_position(mesh, positions, t * 3),
                                                    corner_position(mesh, positions, t * 3 + 1),
                                                    corner_position(mesh, positions, t * 3 + 2));
        }
    }
    return out;
}

// The crease vote: smooth unless the faces bend more than the angle in at least half of the
// poses where both have area. A face with no area in any pose joins nothing: it has no normal
// to agree with, and letting it join would bridge the two sides of a crease it lies on.
bool smooth_between(const std::vector<glm::vec3>& normals, uint32_t num_poses, size_t a, size_t b,
                    float cos_crease) {
    uint32_t voting = 0, sharp = 0;
    for (uint32_t pose = 0; pose < num_poses; ++pose) {
        const glm::vec3& na = normals[a * num_poses + pose];
        const glm::vec3& nb = normals[b * num_poses + pose];
        if (na == glm::vec3(0.0f) || nb == glm::vec3(0.0f)) continue;
        ++voting;
        if (glm::dot(na, nb) < cos_crease) ++sharp;
    }
    return voting > 0 && sharp * 2 < voting;
}

// Do triangles a and b share an edge through welded vertex w (another welded corner in common)?
bool share_edge_at(const SmoothingMesh& mesh, size_t a, size_t b, uint32_t w) {
    for (int i = 0; i < 3; ++i) {
        const uint32_t x = weld_of_corner(mesh, a * 3 + i);
        if (x == w) continue;
        for (int j = 0; j < 3; ++j) {
            if (weld_of_corner(mesh, b * 3 + j) == x) return true;
        }
    }
    return false;
}

uint32_t find_root(std::vector<uint32_t>& parent, uint32_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
}

// Per corner: its group, grouping each welded vertex's corners into connected smooth fans.
void group_corners(const SmoothingMesh& mesh, const std::vector<glm::vec3>& normals,
                   uint32_t num_poses, float cos_crease, SmoothingLayout& layout) {
    const size_t corners = mesh.indices.size();
    // Corners by welded vertex (counting sort).
    std::vector<uint32_t> start(mesh.num_positions() + 1, 0);
    for (size_t c = 0; c < corners; ++c) ++start[weld_of_corner(mesh, c) + 1];
    std::partial_sum(start.begin(), start.end(), start.begin());
    std::vector<uint32_t> by_weld(corners), fill(start.begin(), start.end() - 1);
    for (size_t c = 0; c < corners; ++c) by_weld[fill[weld_of_corner(mesh, c)]++] = uint32_t(c);

    std::vector<uint32_t> parent(corners);
    std::iota(parent.begin(), parent.end(), 0u);
    layout.corner_group.assign(corners, kNone);
    for (uint32_t w = 0; w < mesh.num_positions(); ++w) {
        for (uint32_t i = start[w]; i < start[w + 1]; ++i) {
            for (uint32_t j = i + 1; j < start[w + 1]; ++j) {
                const size_t a = by_weld[i] / 3, b = by_weld[j] / 3;
                const bool join = a == b || (share_edge_at(mesh, a, b, w) &&
                                             smooth_between(normals, num_poses, a, b, cos_crease));
                if (join) parent[find_root(parent, by_weld[i])] = find_root(parent, by_weld[j]);
            }
        }
        for (uint32_t i = start[w]; i < start[w + 1]; ++i) {
            const uint32_t root = find_root(parent, by_weld[i]);
            if (layout.corner_group[root] == kNone) {
                layout.corner_group[root] = layout.num_groups();
                layout.group_weld.push_back(w);
            }
            layout.corner_group[by_weld[i]] = layout.corner_group[root];
        }
    }
}

// Drawn vertices first; a (drawn vertex, group) pair other than the vertex's first one gets
// an appended copy.
void assign_vertices(const SmoothingMesh& mesh, SmoothingLayout& layout) {
    const uint32_t drawn = uint32_t(mesh.vertex_position.size());
    layout.num_drawn_vertices = drawn;
    layout.source_vertex.resize(drawn);
    std::iota(layout.source_vertex.begin(), layout.source_vertex.end(), 0u);
    layout.vertex_group.assign(drawn, kNone);
    layout.indices.resize(mesh.indices.size());
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> copies;
    for (size_t c = 0; c < mesh.indices.size(); ++c) {
        const uint32_t d = mesh.indices[c], g = layout.corner_group[c];
        if (layout.vertex_group[d] == kNone) layout.vertex_group[d] = g;
        if (layout.vertex_group[d] == g) {
            layout.indices[c] = d;
            continue;
        }
        auto [it, added] = copies.try_emplace({d, g}, layout.num_vertices());
        if (added) {
            layout.source_vertex.push_back(d);
            layout.vertex_group.push_back(g);
        }
        layout.indices[c] = it->second;
    }
}

}  // namespace

SmoothingLayout plan_smoothing_groups(const SmoothingMesh& mesh, std::span<const glm::vec3> poses,
                                      uint32_t num_poses, float crease_degrees) {
    SmoothingLayout layout;
    layout.error = check_mesh(mesh);
    if (layout.error.empty() && poses.size() < size_t(num_poses) * mesh.num_positions()) {
        layout.error = "fewer positions than poses x positions";
    }
    if (!layout.error.empty()) return layout;
    // At 180 degrees nothing is a crease, even two faces folded flat onto each other (a dot
    // product is never below -2).
    const float cos_crease =
        crease_degrees >= 180.0f ? -2.0f : std::cos(glm::radians(std::max(crease_degrees, 0.0f)));
    const std::vector<glm::vec3> normals = face_normals(mesh, poses, num_poses);
    group_corners(mesh, normals, num_poses, cos_crease, layout);
    assign_vertices(mesh, layout);
    return layout;
}

void compute_smooth_normals(const SmoothingMesh& mesh, const SmoothingLayout& layout,
                            std::span<const glm::vec3> positions, std::vector<glm::vec3>& out) {
    out.assign(layout.num_vertices(), glm::vec3(0.0f, 0.0f, 1.0f));
    if (!layout.error.empty() || positions.size() < mesh.num_positions() ||
        layout.corner_group.size() != mesh.indices.size()) {
        return;
    }
    std::vector<glm::vec3> group_sum(layout.num_groups(), glm::vec3(0.0f));
    std::vector<glm::vec3> weld_sum(mesh.num_positions(), glm::vec3(0.0f));
    for (size_t t = 0; t * 3 < mesh.indices.size(); ++t) {
        const glm::vec3 p[3] = {corner_position(mesh, positions, t * 3),
                                corner_position(mesh, positions, t * 3 + 1),
                                corner_position(mesh, positions, t * 3 + 2)};
        const glm::vec3 n = face_normal(p[0], p[1], p[2]);
        if (n == glm::vec3(0.0f)) continue;
        for (int k = 0; k < 3; ++k) {
            const glm::vec3 weighted = n * corner_angle(p[k], p[(k + 1) % 3], p[(k + 2) % 3]);
            const uint32_t g = layout.corner_group[t * 3 + k];
            group_sum[g] += weighted;
            weld_sum[layout.group_weld[g]] += weighted;
        }
    }
    for (uint32_t v = 0; v < layout.num_vertices(); ++v) {
        const uint32_t g = layout.vertex_group[v];
        if (g == kNone) continue;
        glm::vec3 n = group_sum[g];
        if (!(glm::length(n) > 1e-12f)) n = weld_sum[layout.group_weld[g]];
        if (glm::length(n) > 1e-12f) out[v] = glm::normalize(n);
    }
}

SmoothingMesh alias_smoothing_mesh(const nqr_alias_model& model, const classic::AliasMesh& mesh) {
    SmoothingMesh out;
    out.indices = mesh.indices;
    out.vertex_position.reserve(mesh.vertices.size());
    for (const classic::AliasMeshVertex& v : mesh.vertices)
        out.vertex_position.push_back(v.pose_vertex);
    const adjacency::AliasSource source(model);
    out.position_weld = adjacency::weld_coincident_vertices(source).class_of;
    return out;
}

std::vector<glm::vec3> alias_pose_positions(const nqr_alias_model& model) {
    const adjacency::AliasSource source(model);
    std::vector<glm::vec3> out;
    out.reserve(size_t(source.num_poses()) * source.num_vertices());
    for (uint32_t pose = 0; pose < source.num_poses(); ++pose) {
        for (uint32_t v = 0; v < source.num_vertices(); ++v)
            out.push_back(source.position(pose, v));
    }
    return out;
}

AliasSmoothNormals compute_alias_smooth_normals(const nqr_alias_model& model,
                                                const classic::AliasMesh& mesh,
                                                float crease_degrees) {
    AliasSmoothNormals out;
    const SmoothingMesh smoothing = alias_smoothing_mesh(model, mesh);
    const std::vector<glm::vec3> poses = alias_pose_positions(model);
    const uint32_t num_poses =
        smoothing.num_positions() ? uint32_t(poses.size() / smoothing.num_positions()) : 0;
    out.layout = plan_smoothing_groups(smoothing, poses, num_poses, crease_degrees);
    if (!out.layout.error.empty()) return out;
    out.num_poses = num_poses;
    out.normals.reserve(size_t(num_poses) * out.layout.num_vertices());
    std::vector<glm::vec3> pose_normals;
    for (uint32_t pose = 0; pose < num_poses; ++pose) {
        compute_smooth_normals(
            smoothing, out.layout,
            std::span<const glm::vec3>(poses).subspan(size_t(pose) * smoothing.num_positions(),
                                                      smoothing.num_positions()),
            pose_normals);
        out.normals.insert(out.normals.end(), pose_normals.begin(), pose_normals.end());
    }
    return out;
}

}  // namespace nq::npr::illustrative

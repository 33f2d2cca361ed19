#include "technical/alias_edge_mesh.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "adjacency/model_adjacency.h"
#include "classic/alias_mesh.h"
#include "technical/shadow_mesh.h"

namespace nq::npr::technical {
namespace {

bool usable_triangle(const nqr_alias_model& model, const int32_t* corners) {
    for (int k = 0; k < 3; ++k) {
        if (corners[k] < 0 || static_cast<uint32_t>(corners[k]) >= model.num_vertices) {
            return false;
        }
    }
    return corners[0] != corners[1] && corners[1] != corners[2] && corners[2] != corners[0];
}

// The file's triangles (clockwise seen from outside), turned counter-clockwise.
std::vector<AliasEdgeMesh::Triangle> file_triangles(const nqr_alias_model& model) {
    std::vector<AliasEdgeMesh::Triangle> out;
    out.reserve(model.num_triangles);
    for (uint32_t t = 0; t < model.num_triangles; ++t) {
        const int32_t* corners = model.triangles + static_cast<size_t>(t) * 4 + 1;
        if (!usable_triangle(model, corners)) continue;
        out.push_back({static_cast<uint32_t>(corners[0]), static_cast<uint32_t>(corners[2]),
                       static_cast<uint32_t>(corners[1])});
    }
    return out;
}

// One record per mesh edge, in MDL indices: (third corner of face0, v0, v1, far corner of the
// neighbour), from face0's slice of triangles_adjacency. On an open border the "far corner" is
// face0's own third corner.
std::vector<std::array<uint32_t, 4>> edge_records(const adjacency::EdgeTable& table) {
    std::vector<std::array<uint32_t, 4>> out;
    out.reserve(table.edges.size());
    for (uint32_t e = 0; e < table.edges.size(); ++e) {
        const uint32_t face = table.edges[e].face0;
        const auto& sides = table.face_edges[face];
        const uint32_t* corners = table.triangles_adjacency.data() + size_t(face) * 6;
        for (uint32_t k = 0; k < 3; ++k) {
            if (sides[k] != e) continue;
            out.push_back({corners[2 * ((k + 2) % 3)], corners[2 * k], corners[2 * ((k + 1) % 3)],
                           corners[2 * k + 1]});
            break;
        }
    }
    return out;
}

// Per MDL vertex, an id shared by every MDL vertex at the same welded position (a skin seam
// duplicates vertices in the file); vertices no welded face uses keep an id of their own.
std::vector<uint32_t> welded_positions(const adjacency::BuiltMesh& built, uint32_t vertex_count) {
    constexpr uint32_t kOwnId = 0x80000000u;
    std::vector<uint32_t> ids(vertex_count);
    for (uint32_t v = 0; v < vertex_count; ++v) ids[v] = kOwnId | v;
    for (size_t f = 0; f < built.face_corners.size(); ++f) {
        for (int k = 0; k < 3; ++k) {
            const uint32_t mdl = built.face_corners[f][k];
            const uint32_t mesh_vertex = built.face_vertices[f][k];
            if (mdl < vertex_count && mesh_vertex < built.vertex_welded.size()) {
                ids[mdl] = built.vertex_welded[mesh_vertex];
            }
        }
    }
    return ids;
}

// Per MDL vertex, the first MDL vertex with its id.
std::vector<uint32_t> representatives(const std::vector<uint32_t>& ids) {
    std::unordered_map<uint32_t, uint32_t> first;
    std::vector<uint32_t> out(ids.size());
    for (uint32_t v = 0; v < ids.size(); ++v) out[v] = first.emplace(ids[v], v).first->second;
    return out;
}

// For each triangle side, the triangle sharing it (by welded position) with opposite winding,
// when exactly two triangles use that side.
std::vector<std::array<int32_t, 3>> side_twins(const std::vector<AliasEdgeMesh::Triangle>& tris,
                                               const std::vector<uint32_t>& ids) {
    struct Side {
        uint32_t lo, hi, triangle, k;
        bool operator<(const Side& o) const { return lo != o.lo ? lo < o.lo : hi < o.hi; }
    };
    const auto id = [&](uint32_t t, uint32_t k) { return ids[tris[t][k % 3]]; };
    std::vector<Side> sides;
    sides.reserve(tris.size() * 3);
    for (uint32_t t = 0; t < tris.size(); ++t) {
        for (uint32_t k = 0; k < 3; ++k) {
            const uint32_t a = id(t, k), b = id(t, k + 1);
            if (a != b) sides.push_back({std::min(a, b), std::max(a, b), t, k});
        }
    }
    std::sort(sides.begin(), sides.end());
    std::vector<std::array<int32_t, 3>> twins(tris.size(), {-1, -1, -1});
    for (size_t i = 0; i < sides.size();) {
        size_t j = i;
        while (j < sides.size() && sides[j].lo == sides[i].lo && sides[j].hi == sides[i].hi) ++j;
        if (j - i == 2) {
            const Side &x = sides[i], &y = sides[i + 1];
            // Opposite winding: x runs a->b, y runs b->a.
            if (id(x.triangle, x.k) == id(y.triangle, y.k + 1)) {
                twins[x.triangle][x.k] = static_cast<int32_t>(y.triangle);
                twins[y.triangle][y.k] = static_cast<int32_t>(x.triangle);
            }
        }
        i = j;
    }
    return twins;
}

bool faces_eye(const glm::vec3& normal, const glm::vec3& point, const glm::vec3& eye) {
    return glm::dot(normal, eye - point) > 0.0f;
}

bool degenerate(const glm::vec3& normal) {
    return glm::dot(normal, normal) < 1e-10f;
}

}  // namespace

std::unique_ptr<AliasEdgeMesh> AliasEdgeMesh::create(const nqr_alias_model& model,
                                                     std::string& error) {
    if (!classic::validate_alias_model(model, error)) return nullptr;
    adjacency::ModelAdjacency recovered = adjacency::recover_adjacency(model);
    std::unique_ptr<AliasEdgeMesh> mesh(new AliasEdgeMesh());
    mesh->stats_ = recovered.stats;
    mesh->verdict_ = std::move(recovered.verdict);
    mesh->vertex_count_ = model.num_vertices;
    mesh->edges_ = edge_records(recovered.edges);
    mesh->triangles_ = file_triangles(model);
    mesh->shadow_triangles_ = technical::shadow_triangles(recovered.mesh);
    if (mesh->shadow_triangles_.empty()) mesh->shadow_triangles_ = mesh->triangles_;
    const std::vector<uint32_t> welded = welded_positions(recovered.mesh, model.num_vertices);
    mesh->twins_ = side_twins(mesh->triangles_, welded);
    mesh->seam_representatives_ = representatives(welded);
    mesh->facing_away_.reserve(mesh->triangles_.size());
    return mesh;
}

void AliasEdgeMesh::find_edges(const glm::vec3* pose, const glm::vec3& eye, const EdgeQuery& query,
                               std::vector<FoundEdge>& out) const {
    if (!pose) return;
    if (query.backface_lines) find_backface_lines(pose, eye, out);
    if (query.silhouettes || query.creases) find_true_edges(pose, eye, query, out);
}

void AliasEdgeMesh::find_true_edges(const glm::vec3* pose, const glm::vec3& eye,
                                    const EdgeQuery& query, std::vector<FoundEdge>& out) const {
    // With back-face lines standing in for silhouettes, an edge between a front and a back face
    // is theirs: it is neither drawn here nor a crease.
    const bool silhouettes_elsewhere = query.backface_lines;
    for (const auto& [third_index, i0, i1, far_index] : edges_) {
        if (far_index == third_index) {  // an open border
            if (query.silhouettes) out.push_back({i0, i1, EdgeKind::silhouette});
            continue;
        }
        const glm::vec3 &third = pose[third_index], &p0 = pose[i0];
        const glm::vec3 &p1 = pose[i1], &far = pose[far_index];
        const glm::vec3 n0 = glm::cross(p1 - p0, third - p0);
        const glm::vec3 n1 = glm::cross(p0 - p1, far - p1);
        if (degenerate(n0) || degenerate(n1)) continue;
        const bool front0 = faces_eye(n0, p0, eye), front1 = faces_eye(n1, p1, eye);
        if (front0 != front1 && (query.silhouettes || silhouettes_elsewhere)) {
            if (query.silhouettes) out.push_back({i0, i1, EdgeKind::silhouette});
            continue;
        }
        if (!query.creases || !(front0 || front1)) continue;
        if (glm::dot(glm::normalize(n0), glm::normalize(n1)) >= query.cos_crease) continue;
        // Convex (a ridge) when the neighbour's far corner lies behind face0's plane.
        const bool convex = glm::dot(n0, far - p0) < 0.0f;
        out.push_back({i0, i1, convex ? EdgeKind::ridge : EdgeKind::valley});
    }
}

void AliasEdgeMesh::find_backface_lines(const glm::vec3* pose, const glm::vec3& eye,
                                        std::vector<FoundEdge>& out) const {
    facing_away_.resize(triangles_.size());
    for (size_t t = 0; t < triangles_.size(); ++t) {
        const Triangle& tri = triangles_[t];
        const glm::vec3& p0 = pose[tri[0]];
        const glm::vec3 normal = glm::cross(pose[tri[1]] - p0, pose[tri[2]] - p0);
        facing_away_[t] = !degenerate(normal) && !faces_eye(normal, p0, eye);
    }
    for (size_t t = 0; t < triangles_.size(); ++t) {
        if (!facing_away_[t]) continue;
        for (uint32_t k = 0; k < 3; ++k) {
            const int32_t twin = twins_[t][k];
            if (twin >= 0 && facing_away_[static_cast<size_t>(twin)]) continue;  // hidden
            out.push_back({triangles_[t][k], triangles_[t][(k + 1) % 3], EdgeKind::backface});
        }
    }
}

EdgeQuery plan_edge_query(const AliasEdgeMesh& mesh, const EdgeSettings& s) {
    const bool fallback = s.backface_lines == BackfaceLines::always ||
                          (s.backface_lines == BackfaceLines::unclean_models && !mesh.clean());
    const bool has_adjacency = mesh.edge_count() > 0;
    EdgeQuery query;
    query.backface_lines = s.silhouettes && fallback && !mesh.triangles().empty();
    query.silhouettes = s.silhouettes && !fallback && has_adjacency;
    query.creases =
        s.creases && has_adjacency && (mesh.clean() || s.backface_lines == BackfaceLines::never);
    query.cos_crease = std::cos(glm::radians(std::clamp(s.crease_angle_degrees, 0.0f, 180.0f)));
    return query;
}

std::string AliasEdgeMesh::verdict_line(const std::string& model_name) const {
    return "adjacency: " + model_name + ": " + adjacency::edge_style_name(verdict_.style) + " (" +
           verdict_.reason + ")";
}

}  // namespace nq::npr::technical

#include "render/occluder_mesh.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <glm/glm.hpp>

#include "formats/bsp.h"

namespace nq {

namespace {

// Fence textures ("{" names) have see-through texels; sky and liquids may be drawn see-through
// or far away (r_wateralpha, sky boxes); a face without its texture is drawn with a stand-in.
bool face_occludes(const nqr_brush_model& brush, const nqr_surface& s) {
    if (s.num_vertices < 3 || s.num_vertices > brush.num_vertices ||
        s.first_vertex > brush.num_vertices - s.num_vertices) {
        return false;
    }
    if (s.flags & (NQR_SURFACE_SKY | NQR_SURFACE_LIQUID)) return false;
    if (s.texture < 0 || static_cast<uint32_t>(s.texture) >= brush.num_textures) return false;
    const nqr_texture& texture = brush.textures[s.texture];
    if (texture.flags & (NQR_TEXTURE_SKY | NQR_TEXTURE_LIQUID | NQR_TEXTURE_MISSING)) return false;
    if (texture.name == nullptr || texture.name[0] == '{') return false;
    return std::isfinite(s.normal[0]) && std::isfinite(s.normal[1]) && std::isfinite(s.normal[2]);
}

// The rasteriser fills the intersection of the edges' inner sides, which is the polygon only when
// it is convex (a malformed map may hold anything).
bool polygon_convex(const float* positions, const nqr_surface& s) {
    const glm::dvec3 n(s.normal[0], s.normal[1], s.normal[2]);
    const auto at = [&](uint32_t k) {
        const float* p = positions + size_t{s.first_vertex + k % s.num_vertices} * 3;
        return glm::dvec3(p[0], p[1], p[2]);
    };
    for (uint32_t k = 0; k < s.num_vertices; ++k) {
        const glm::dvec3 turn = glm::cross(at(k + 1) - at(k), at(k + 2) - at(k + 1));
        if (!(glm::dot(turn, n) > -0.01)) return false;
    }
    return true;
}

uint64_t half_edge_key(uint32_t from, uint32_t to) {
    return (uint64_t{from} << 32) | to;
}

}  // namespace

std::vector<SurfaceRange> bsp_model_ranges(const Bsp& bsp) {
    std::vector<SurfaceRange> out;
    const auto faces = static_cast<uint32_t>(bsp.faces.size());
    for (const BspModel& m : bsp.models) {
        const uint32_t first = std::min(m.first_face, faces);
        out.push_back({first, std::min(m.num_faces, faces - first)});
    }
    return out;
}

OccluderMesh::OccluderMesh(const nqr_brush_model& brush, std::span<const SurfaceRange> models)
    : positions_(brush.positions), vertex_ids_(brush.vertex_ids) {
    faces_.resize(brush.num_surfaces);
    face_model_.assign(brush.num_surfaces, UINT32_MAX);
    vertex_face_.assign(brush.num_vertices, UINT32_MAX);
    for (uint32_t m = 0; m < models.size(); ++m) {
        const uint32_t first = std::min(models[m].first, brush.num_surfaces);
        const uint32_t end = first + std::min(models[m].count, brush.num_surfaces - first);
        for (uint32_t f = first; f < end; ++f) {
            if (face_model_[f] == UINT32_MAX) face_model_[f] = m;
        }
    }
    for (uint32_t f = 0; f < brush.num_surfaces; ++f) {
        const nqr_surface& s = brush.surfaces[f];
        OccluderFace& face = faces_[f];
        if (face_model_[f] == UINT32_MAX || !face_occludes(brush, s) ||
            !polygon_convex(brush.positions, s)) {
            continue;
        }
        face.first_vertex = s.first_vertex;
        face.num_vertices = s.num_vertices;
        const glm::vec3 normal(s.normal[0], s.normal[1], s.normal[2]);
        const float length = glm::length(normal);
        if (!(length > 0.5f)) continue;
        face.normal = normal / length;
        face.dist = s.dist / length;
        double lowest = face.dist;
        for (uint32_t k = 0; k < s.num_vertices; ++k) {
            lowest = std::min(lowest, double(glm::dot(face.normal, position(s.first_vertex + k))));
            vertex_face_[s.first_vertex + k] = f;
        }
        // A hundredth of a unit more for the rounding of the products above.
        face.back_dist = static_cast<float>(lowest - 0.01);
        face.occludes = std::isfinite(face.back_dist) && std::isfinite(face.dist);
        max_polygon_vertices_ = std::max(max_polygon_vertices_, s.num_vertices);
    }
    link_partners();
}

glm::vec3 OccluderMesh::position(uint32_t vertex) const {
    const float* p = positions_ + size_t{vertex} * 3;
    return {p[0], p[1], p[2]};
}

std::span<const uint32_t> OccluderMesh::partners(uint32_t vertex) const {
    if (vertex + 1 >= partner_start_.size()) return {};
    return std::span<const uint32_t>(partners_).subspan(
        partner_start_[vertex], partner_start_[vertex + 1] - partner_start_[vertex]);
}

void OccluderMesh::link_partners() {
    struct HalfEdge {
        uint64_t key;
        uint32_t face;
    };
    std::vector<HalfEdge> edges;
    const auto next_of = [&](uint32_t v) {
        const OccluderFace& face = faces_[vertex_face_[v]];
        return v + 1 == face.first_vertex + face.num_vertices ? face.first_vertex : v + 1;
    };
    for (uint32_t v = 0; v < vertex_face_.size(); ++v) {
        if (vertex_face_[v] == UINT32_MAX || !faces_[vertex_face_[v]].occludes) continue;
        edges.push_back({half_edge_key(vertex_ids_[v], vertex_ids_[next_of(v)]), vertex_face_[v]});
    }
    std::sort(edges.begin(), edges.end(),
              [](const HalfEdge& a, const HalfEdge& b) { return a.key < b.key; });
    partner_start_.assign(vertex_face_.size() + 1, 0);
    for (uint32_t v = 0; v < vertex_face_.size(); ++v) {
        partner_start_[v] = static_cast<uint32_t>(partners_.size());
        if (vertex_face_[v] == UINT32_MAX || !faces_[vertex_face_[v]].occludes) continue;
        const uint32_t from = vertex_ids_[v], to = vertex_ids_[next_of(v)];
        if (from == to) continue;
        auto range =
            std::equal_range(edges.begin(), edges.end(), HalfEdge{half_edge_key(to, from), 0},
                             [](const HalfEdge& a, const HalfEdge& b) { return a.key < b.key; });
        const uint32_t face = vertex_face_[v];
        for (auto it = range.first; it != range.second; ++it) {
            if (it->face != face && face_model_[it->face] == face_model_[face]) {
                partners_.push_back(it->face);
            }
        }
    }
    partner_start_.back() = static_cast<uint32_t>(partners_.size());
}

}  // namespace nq

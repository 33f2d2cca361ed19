#include "technical/brush_edge_table.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "abi/abi_access.h"
#include "technical/brush_edge_tjunctions.h"
#include "technical/technical_settings.h"

namespace nq::npr::technical {
namespace {

using npr::abi_element;

struct HalfEdge {
    uint32_t surface;
    uint32_t id0, id1;  // BSP vertex ids, in the order the surface walks them
    glm::vec3 p0, p1;
};

glm::vec3 position(const nqr_brush_model& brush, uint32_t vertex) {
    return glm::make_vec3(brush.positions + static_cast<size_t>(vertex) * 3);
}

// Finite and within any map's reach (corrupt data must not overflow the spatial hash).
bool usable_position(const glm::vec3& p) {
    constexpr float kLimit = 1.0e6f;
    return std::abs(p.x) < kLimit && std::abs(p.y) < kLimit && std::abs(p.z) < kLimit;
}

glm::vec3 normal_of(const nqr_brush_model& brush, uint32_t surface) {
    return glm::make_vec3(abi_element(brush.surfaces, surface).normal);
}

std::vector<HalfEdge> collect_half_edges(const nqr_brush_model& brush, BrushEdgeStats& stats) {
    std::vector<HalfEdge> half_edges;
    for (uint32_t s = 0; s < brush.num_surfaces; ++s) {
        if (!surface_owns_edges(brush, s)) continue;
        ++stats.surfaces;
        const nqr_surface& surface = abi_element(brush.surfaces, s);
        for (uint32_t i = 0; i < surface.num_vertices; ++i) {
            const uint32_t a = surface.first_vertex + i;
            const uint32_t b = surface.first_vertex + (i + 1) % surface.num_vertices;
            const HalfEdge h{s, brush.vertex_ids[a], brush.vertex_ids[b], position(brush, a),
                             position(brush, b)};
            // Repeated polygon vertices give sides of no length: no edge there.
            if (h.id0 == h.id1 || glm::length(h.p1 - h.p0) <= kOnLineTolerance) continue;
            if (!usable_position(h.p0) || !usable_position(h.p1)) continue;
            half_edges.push_back(h);
        }
    }
    stats.half_edges = static_cast<uint32_t>(half_edges.size());
    return half_edges;
}

BrushEdge shared_edge(const nqr_brush_model& brush, uint32_t face0, uint32_t face1,
                      const glm::vec3& v0, const glm::vec3& v1) {
    BrushEdge edge{v0, v1, face0, face1, 0.0f};
    const glm::vec3 direction = glm::normalize(v1 - v0);
    edge.dihedral_degrees =
        brush_rotation_degrees(normal_of(brush, face0), direction, normal_of(brush, face1)) -
        180.0f;
    return edge;
}

// Pairs half-edges by their vertex ids: a pair of ids walked once each way, by two different
// surfaces and nobody else, is a shared edge. Everything else is returned for geometric
// matching (`loose` holds indices into half_edges). Half-edges are grouped by their pair of ids
// with a counting sort on the lower id (ids are below id_count), then by the higher id.
std::vector<BrushEdge> match_by_ids(const nqr_brush_model& brush,
                                    const std::vector<HalfEdge>& half_edges, uint64_t id_count,
                                    std::vector<uint32_t>& loose) {
    std::vector<uint32_t> first(id_count + 1, 0);
    for (const HalfEdge& h : half_edges) ++first[std::min(h.id0, h.id1) + 1];
    std::partial_sum(first.begin(), first.end(), first.begin());
    // Per lower id, (higher id << 32 | half-edge index): sorting a bucket sorts by both.
    std::vector<uint64_t> keyed(half_edges.size());
    std::vector<uint32_t> next(first.begin(), first.end() - 1);
    for (uint32_t i = 0; i < half_edges.size(); ++i) {
        const HalfEdge& h = half_edges[i];
        keyed[next[std::min(h.id0, h.id1)]++] = uint64_t{std::max(h.id0, h.id1)} << 32 | i;
    }
    std::vector<BrushEdge> shared;
    for (uint64_t id = 0; id < id_count; ++id) {
        const auto bucket_begin = keyed.begin() + first[id];
        const auto bucket_end = keyed.begin() + first[id + 1];
        std::sort(bucket_begin, bucket_end);  // few half-edges meet at one vertex
        for (auto begin = bucket_begin; begin != bucket_end;) {
            auto end = begin;
            while (end != bucket_end && (*end >> 32) == (*begin >> 32)) ++end;
            const HalfEdge* a = &half_edges[static_cast<uint32_t>(*begin)];
            const HalfEdge* b =
                end - begin == 2 ? &half_edges[static_cast<uint32_t>(*(begin + 1))] : nullptr;
            if (b && a->surface != b->surface && a->id0 == b->id1) {
                if (b->surface < a->surface) std::swap(a, b);
                shared.push_back(shared_edge(brush, a->surface, b->surface, a->p0, a->p1));
            } else {
                for (auto k = begin; k != end; ++k) loose.push_back(static_cast<uint32_t>(*k));
            }
            begin = end;
        }
    }
    return shared;
}

// Ids are BSP vertex indices; anything far beyond what a BSP can hold is corrupt data.
constexpr uint32_t kMaxVertexIds = 1u << 26;

uint64_t vertex_id_count(const nqr_brush_model& brush) {
    uint64_t count = 0;
    for (uint32_t v = 0; v < brush.num_vertices; ++v) {
        count = std::max(count, uint64_t{brush.vertex_ids[v]} + 1);
    }
    return count;
}

uint32_t find_root(std::vector<uint32_t>& parent, uint32_t x) {
    while (parent[x] != x) {
        parent[x] = parent[parent[x]];
        x = parent[x];
    }
    return x;
}

// Connected pieces of the model through shared vertex ids, per surface. Quake's compilers number
// vertices per model, so a door never joins the wall around it, even where their sides line up.
std::vector<uint32_t> surface_components(const nqr_brush_model& brush) {
    std::vector<uint32_t> parent(vertex_id_count(brush));
    std::iota(parent.begin(), parent.end(), 0u);
    std::vector<uint32_t> component(brush.num_surfaces, 0);
    for (uint32_t s = 0; s < brush.num_surfaces; ++s) {
        if (!surface_owns_edges(brush, s)) continue;
        const nqr_surface& surface = abi_element(brush.surfaces, s);
        const uint32_t first = find_root(parent, brush.vertex_ids[surface.first_vertex]);
        for (uint32_t i = 1; i < surface.num_vertices; ++i) {
            parent[find_root(parent, brush.vertex_ids[surface.first_vertex + i])] = first;
        }
    }
    for (uint32_t s = 0; s < brush.num_surfaces; ++s) {
        if (!surface_owns_edges(brush, s)) continue;
        component[s] =
            find_root(parent, brush.vertex_ids[abi_element(brush.surfaces, s).first_vertex]);
    }
    return component;
}

void match_geometrically(const nqr_brush_model& brush, const std::vector<HalfEdge>& half_edges,
                         const std::vector<uint32_t>& loose, std::vector<BrushEdge>& edges,
                         BrushEdgeStats& stats) {
    const std::vector<uint32_t> component = surface_components(brush);
    std::vector<LooseHalfEdge> input(loose.size());
    for (size_t i = 0; i < loose.size(); ++i) {
        const HalfEdge& h = half_edges[loose[i]];
        input[i] = {h.p0, h.p1, normal_of(brush, h.surface), h.surface, component[h.surface]};
    }
    const CollinearMatching matching = match_collinear_half_edges(input);
    for (const CollinearMatch& m : matching.matches) {
        uint32_t face0 = input[m.a].surface, face1 = input[m.b].surface;
        glm::vec3 from = m.from, to = m.to;
        if (face1 < face0) {
            std::swap(face0, face1);
            std::swap(from, to);
        }
        edges.push_back(shared_edge(brush, face0, face1, from, to));
    }
    stats.t_junction_edges = static_cast<uint32_t>(matching.matches.size());

    std::vector<CrossableFace> faces;
    std::vector<glm::vec3> corners;
    for (uint32_t s = 0; s < brush.num_surfaces; ++s) {
        if (!surface_owns_edges(brush, s)) continue;
        const nqr_surface& surface = abi_element(brush.surfaces, s);
        CrossableFace face;
        face.first_corner = static_cast<uint32_t>(corners.size());
        face.num_corners = surface.num_vertices;
        face.normal = normal_of(brush, s);
        face.dist = surface.dist;
        face.surface = s;
        face.component = component[s];
        // Corrupt planes must not turn into matches (or into NaN angles to sort by).
        bool usable = std::abs(glm::length(face.normal) - 1.0f) < 0.01f && std::isfinite(face.dist);
        for (uint32_t i = 0; i < surface.num_vertices; ++i) {
            corners.push_back(position(brush, surface.first_vertex + i));
            usable = usable && usable_position(corners.back());
        }
        if (usable) faces.push_back(face);
    }
    const FaceCrossingMatching crossing =
        match_pieces_inside_faces(input, matching.uncovered, faces, corners);
    for (const FaceCrossing& m : crossing.matches) {
        uint32_t face0 = input[m.half_edge].surface, face1 = faces[m.face].surface;
        glm::vec3 from = m.from, to = m.to;
        if (face1 < face0) {  // the face's half meets the piece walking it the other way
            std::swap(face0, face1);
            std::swap(from, to);
        }
        edges.push_back(shared_edge(brush, face0, face1, from, to));
    }
    for (const UncoveredPiece& piece : crossing.uncovered) {
        edges.push_back({piece.from, piece.to, input[piece.half_edge].surface, kNoFace, 0.0f});
    }
    stats.inside_face_edges = static_cast<uint32_t>(crossing.matches.size());
    stats.boundary_edges = static_cast<uint32_t>(crossing.uncovered.size());
}

}  // namespace

bool surface_owns_edges(const nqr_brush_model& brush, uint32_t surface_index) {
    const nqr_surface& surface = abi_element(brush.surfaces, surface_index);
    const bool polygon_ok = surface.num_vertices >= 3 &&
                            surface.first_vertex <= brush.num_vertices &&
                            surface.num_vertices <= brush.num_vertices - surface.first_vertex;
    if (!polygon_ok || (surface.flags & NQR_SURFACE_SKY)) return false;
    if (surface.texture >= 0 && static_cast<uint32_t>(surface.texture) < brush.num_textures) {
        const nqr_texture& texture =
            abi_element(brush.textures, static_cast<uint32_t>(surface.texture));
        if (texture.flags & NQR_TEXTURE_SKY) return false;
    }
    return true;
}

float default_crease_angle_degrees() {
    return EdgeSettings{}.crease_angle_degrees;
}

BrushEdgeTable BrushEdgeTable::build(const nqr_brush_model& brush, std::string& error) {
    BrushEdgeTable table;
    table.index_by_surface(0);
    const bool arrays_ok = (brush.num_surfaces == 0 || npr::has_known_prefix(brush.surfaces)) &&
                           (brush.num_textures == 0 || npr::has_known_prefix(brush.textures));
    if (!arrays_ok || (brush.num_vertices > 0 && (!brush.positions || !brush.vertex_ids))) {
        error = "brush model without usable surfaces, positions or vertex ids";
        return table;
    }
    const uint64_t id_count = vertex_id_count(brush);
    if (id_count > kMaxVertexIds) {
        error = "brush model vertex ids out of range";
        return table;
    }
    const std::vector<HalfEdge> half_edges = collect_half_edges(brush, table.stats_);
    std::vector<uint32_t> loose;
    table.edges_ = match_by_ids(brush, half_edges, id_count, loose);
    table.stats_.shared_edges = static_cast<uint32_t>(table.edges_.size());
    table.stats_.unmatched_half_edges = static_cast<uint32_t>(loose.size());
    match_geometrically(brush, half_edges, loose, table.edges_, table.stats_);
    table.stats_.edges = static_cast<uint32_t>(table.edges_.size());
    const float crease = default_crease_angle_degrees();
    table.stats_.creases = static_cast<uint32_t>(
        std::count_if(table.edges_.begin(), table.edges_.end(), [&](const BrushEdge& e) {
            return !e.is_boundary() && std::abs(e.dihedral_degrees) > crease;
        }));
    table.index_by_surface(brush.num_surfaces);
    return table;
}

void BrushEdgeTable::index_by_surface(uint32_t surface_count) {
    first_edge_.assign(surface_count + 1, 0);
    first_shared_.assign(surface_count + 1, 0);
    for (const BrushEdge& e : edges_) {
        ++first_edge_[e.face0 + 1];
        if (e.is_boundary()) continue;
        ++first_shared_[e.face0 + 1];
        ++first_shared_[e.face1 + 1];
    }
    std::partial_sum(first_edge_.begin(), first_edge_.end(), first_edge_.begin());
    std::partial_sum(first_shared_.begin(), first_shared_.end(), first_shared_.begin());

    // Counting sort by face0 (stable: the order within a surface is the order of discovery).
    std::vector<BrushEdge> by_face(edges_.size());
    std::vector<uint32_t> next(first_edge_.begin(), first_edge_.end() - 1);
    for (const BrushEdge& e : edges_) by_face[next[e.face0]++] = e;
    edges_ = std::move(by_face);
    shared_lists_.assign(first_shared_.back(), 0);
    std::vector<uint32_t> filled(first_shared_.begin(), first_shared_.end() - 1);
    for (uint32_t i = 0; i < edges_.size(); ++i) {
        const BrushEdge& e = edges_[i];
        if (e.is_boundary()) continue;
        shared_lists_[filled[e.face0]++] = i;
        shared_lists_[filled[e.face1]++] = i;
    }
}

uint32_t BrushEdgeTable::range_begin(uint32_t first_surface) const {
    return first_edge_[std::min(first_surface, num_surfaces())];
}

uint32_t BrushEdgeTable::range_end(uint32_t first_surface, uint32_t count) const {
    const uint32_t last = std::min(first_surface, num_surfaces());
    return first_edge_[last + std::min(count, num_surfaces() - last)];
}

std::span<const uint32_t> BrushEdgeTable::shared_edges_of(uint32_t surface) const {
    if (surface >= num_surfaces()) return {};
    return {shared_lists_.data() + first_shared_[surface],
            first_shared_[surface + 1] - first_shared_[surface]};
}

}  // namespace nq::npr::technical

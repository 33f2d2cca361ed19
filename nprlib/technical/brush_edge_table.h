// The edges of a brush model (BSP faces) with the faces on either side, for drawing silhouettes
// and creases of brush geometry. CPU only (no GL), built once per nqr_brush_model.
//
// Every side of every surface's polygon is a half-edge. Sky surfaces own no edges (their
// outline is not geometry anyone sees); liquids do (the waterline is useful).
//   1. Half-edges whose vertex ids (nqr_brush_model.vertex_ids) pair up exactly, two different
//      surfaces and nobody else on that pair of ids, become shared edges.
//   2. Quake maps keep some T-junctions: a long side of one face meets two shorter sides of its
//      neighbours. The half-edges left over are matched geometrically (brush_edge_tjunctions.h):
//      the overlapping part of two collinear, opposite half-edges becomes a shared edge.
//   3. Some sides end on a face that was never split there (a wall against the middle of a
//      pillar's side): the part of a leftover side that runs across the inside of another face
//      of its piece of the model becomes a shared edge with that face.
//   4. What is still uncovered becomes boundary edges (one face only): sides along sky, sides
//      whose partner belongs to another model or piece, lines where more sides run one way than
//      the other (a wall with faces on both sides, into water and into air, meeting a floor).
// Shared edges keep both faces' planes and the signed dihedral angle, the angle between the
// two normals: positive for a ridge (convex), negative for a valley (concave). Whether it is a
// crease (|angle| > the crease cvar) and whether it is a silhouette (one face toward the eye,
// one away) is decided when drawing.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "nqr_renderer.h"

namespace nq::npr::technical {

struct BrushEdgeStats {
    uint32_t surfaces = 0;           // surfaces that own edges (valid polygons, not sky)
    uint32_t edges = 0;              // = shared + T-junction + inside-face + boundary edges
    uint32_t shared_edges = 0;       // matched by vertex ids
    uint32_t t_junction_edges = 0;   // matched geometrically (overlapping collinear sides)
    uint32_t inside_face_edges = 0;  // a side across the inside of another face (step 3)
    uint32_t boundary_edges = 0;     // one face only (whole sides or uncovered parts of them)
    uint32_t creases = 0;            // two-face edges bending more than the default crease angle
    uint32_t half_edges = 0;         // polygon sides of the owning surfaces, zero-length ones out
    uint32_t unmatched_half_edges = 0;  // left after matching by ids: the geometric pass's input
};

inline constexpr uint32_t kNoFace = 0xffffffffu;

struct BrushEdge {
    glm::vec3 v0{0.0f}, v1{0.0f};   // in the direction face0 walks it (counter-clockwise)
    uint32_t face0 = 0;             // surface index; the lower of the two for shared edges
    uint32_t face1 = kNoFace;       // kNoFace: a boundary edge
    float dihedral_degrees = 0.0f;  // + ridge, - valley, 0 for boundary edges
    bool is_boundary() const { return face1 == kNoFace; }
};

class BrushEdgeTable {
  public:
    // Empty table with `error` set when the model lacks the arrays edges are made from.
    static BrushEdgeTable build(const nqr_brush_model& brush, std::string& error);

    // Sorted by face0, so the edges first owned by a range of surfaces are one range.
    const std::vector<BrushEdge>& edges() const { return edges_; }
    const BrushEdgeStats& stats() const { return stats_; }
    uint32_t num_surfaces() const { return static_cast<uint32_t>(first_edge_.size()) - 1; }

    // [begin, end) in edges() of the edges whose face0 lies in [first, first + count).
    uint32_t range_begin(uint32_t first_surface) const;
    uint32_t range_end(uint32_t first_surface, uint32_t count) const;

    // Indices into edges() of the shared (two-face) edges of one surface, as face0 or face1.
    std::span<const uint32_t> shared_edges_of(uint32_t surface) const;

  private:
    // Sorts the edges by face0; builds the per-surface ranges and shared-edge lists.
    void index_by_surface(uint32_t surface_count);

    std::vector<BrushEdge> edges_;
    BrushEdgeStats stats_;
    std::vector<uint32_t> first_edge_;    // per surface + 1: edges sorted by face0
    std::vector<uint32_t> first_shared_;  // per surface + 1: into shared_lists_
    std::vector<uint32_t> shared_lists_;
};

// Whether a surface owns edges: a usable polygon that is not sky.
bool surface_owns_edges(const nqr_brush_model& brush, uint32_t surface);

// The crease angle the stats count with (technical_settings.h's default).
float default_crease_angle_degrees();

}  // namespace nq::npr::technical

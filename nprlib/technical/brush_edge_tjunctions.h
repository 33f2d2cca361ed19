// Geometric matching of the brush half-edges that vertex ids could not pair (T-junctions, and
// lines where more than two faces meet, such as a wall split at a waterline): two half-edges of
// different surfaces that run along one line in opposite directions share the part where they
// overlap. Candidates come from a spatial hash: each half-edge is cut into pieces no longer than
// a hash cell and registered in every cell its piece's box (grown by the tolerance) touches, so
// two overlapping half-edges always meet in some cell, however their lines lie.
//
// Where several partners overlap one stretch, the pairs are taken in order of their rotation
// angle (brush_rotation_degrees): each face pairs with the face it reaches first when turning
// about the line through the empty space in front of it, which is the face it visibly meets.
//
// What is left can still run across the inside of a face (match_pieces_inside_faces).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace nq::npr::technical {

// How far (world units) a point may lie off a line and still count as on it; overlaps and
// leftovers shorter than twice this are ignored.
inline constexpr float kOnLineTolerance = 0.1f;

struct LooseHalfEdge {
    glm::vec3 p0{0.0f}, p1{0.0f};  // as its surface walks it
    glm::vec3 normal{0.0f};        // its surface's
    uint32_t surface = 0;
    uint32_t component = 0;  // only half-edges of one connected piece of the model match
};

struct CollinearMatch {
    uint32_t a = 0, b = 0;           // indices into the input; a < b
    glm::vec3 from{0.0f}, to{0.0f};  // the shared stretch, in the direction a walks it
};

struct UncoveredPiece {
    uint32_t half_edge = 0;
    glm::vec3 from{0.0f}, to{0.0f};  // in the direction the half-edge walks
};

struct CollinearMatching {
    std::vector<CollinearMatch> matches;
    std::vector<UncoveredPiece> uncovered;  // every half-edge's stretches without a partner
};

CollinearMatching match_collinear_half_edges(const std::vector<LooseHalfEdge>& half_edges);

// The faces a leftover piece may run across: convex polygons over one array of corners.
struct CrossableFace {
    uint32_t first_corner = 0, num_corners = 0;  // counter-clockwise seen from the front
    glm::vec3 normal{0.0f};
    float dist = 0.0f;  // front side: dot(normal, p) > dist
    uint32_t surface = 0;
    uint32_t component = 0;
};

struct FaceCrossing {
    uint32_t half_edge = 0;          // whose piece
    uint32_t face = 0;               // index into the faces
    glm::vec3 from{0.0f}, to{0.0f};  // in the direction the half-edge walks
};

struct FaceCrossingMatching {
    std::vector<FaceCrossing> matches;
    std::vector<UncoveredPiece> uncovered;  // what no face took
};

// Pieces that no side matched but that run across the inside of another face of their piece of
// the model: Quake's compilers leave such T-junctions where a wall, pillar or trim ends against
// a face that was never split there. The part of the piece inside a face (whose plane holds the
// piece and is not the piece's own plane; a piece along one of the face's sides is not inside
// it) is shared with the half of that face whose front looks into the same space as the piece's
// face: brush_rotation_degrees with the face's normal measures the turn to that half. Where
// several faces hold one stretch the least turn wins; faces' insides are not used up.
FaceCrossingMatching match_pieces_inside_faces(const std::vector<LooseHalfEdge>& half_edges,
                                               const std::vector<UncoveredPiece>& pieces,
                                               const std::vector<CrossableFace>& faces,
                                               const std::vector<glm::vec3>& corners);

// The angle (degrees, in (0, 360]) a face with `normal0`, whose side runs along `direction0`
// (counter-clockwise seen from its front), turns through the space in front of it to reach the
// face with `normal1` across that side: 180 for coplanar faces, 270 for a convex right angle,
// 90 for a concave one. Minus 180 it is the signed dihedral angle (+ ridge, - valley).
float brush_rotation_degrees(const glm::vec3& normal0, const glm::vec3& direction0,
                             const glm::vec3& normal1);

}  // namespace nq::npr::technical

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

// The angle (degrees, in (0, 360]) a face with `normal0`, whose side runs along `direction0`
// (counter-clockwise seen from its front), turns through the space in front of it to reach the
// face with `normal1` across that side: 180 for coplanar faces, 270 for a convex right angle,
// 90 for a concave one. Minus 180 it is the signed dihedral angle (+ ridge, - valley).
float brush_rotation_degrees(const glm::vec3& normal0, const glm::vec3& direction0,
                             const glm::vec3& normal1);

}  // namespace nq::npr::technical

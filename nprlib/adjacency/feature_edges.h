// The per-frame test of a model's edges on its current pose: which edges are on the outline
// and which are creases, for any positions (the blended pose an entity is drawn with) and a
// real eye. One function, classify_edge, decides; the technical style draws what it says, and
// the tests of this header therefore test what is on screen.
//
// SILHOUETTES. An edge is on the silhouette when one of its faces looks toward the eye and the
// other away: (n0·(e − p0)) (n1·(e − p1)) has the faces on opposite sides, with e the eye in
// model space and p_i a point of face i. The shorter (n0·e)(n1·e) is only right for an eye at
// infinity or planes through the origin, so it is not used. Open borders are always outline.
// A face of no area (a pose can squash one) makes its edges no feature.
//
// CREASES. An edge with at least one face seen whose normals turn by more than the crease
// angle is a crease: a ridge where the surface is convex
// there (the neighbour's far corner lies behind face0's plane), a valley where concave.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "adjacency/edge_table.h"

namespace nq::npr::adjacency {

enum class FeatureEdge : uint8_t { none, border, silhouette, ridge, valley };
const char* feature_edge_name(FeatureEdge kind);

// What the outline is made of, for the edges between a front and a back face:
enum class Outline : uint8_t {
    silhouettes,  // those edges and open borders are the outline (and never creases)
    elsewhere,    // another technique draws the outline: they are neither outline nor crease
    ignored,      // no outline is drawn: they are creases when they turn enough, like any edge
};

struct FeatureTest {
    Outline outline = Outline::silhouettes;
    bool creases = true;
    float cos_crease = 0.5f;  // a crease where the normals' cosine is below this (60 degrees)
};

// The cosine FeatureTest::cos_crease wants for a crease angle in degrees, clamped to 0..180.
float crease_cosine(float degrees);

// A face's unnormalised normal (cross product of two sides) that is long enough to have a
// direction; a pose can squash a face to no area.
inline bool has_area(const glm::vec3& normal) {
    return glm::dot(normal, normal) >= 1e-10f;
}

// Whether a face through `point` with `normal` looks toward `eye`.
inline bool faces_eye(const glm::vec3& normal, const glm::vec3& point, const glm::vec3& eye) {
    return glm::dot(normal, eye - point) > 0.0f;
}

inline FeatureEdge classify_edge(const EdgeRecord& edge, const glm::vec3* positions,
                                 const glm::vec3& eye, const FeatureTest& test) {
    if (edge.border()) {
        return test.outline == Outline::silhouettes ? FeatureEdge::border : FeatureEdge::none;
    }
    const glm::vec3 &third = positions[edge.third], &p0 = positions[edge.v0];
    const glm::vec3 &p1 = positions[edge.v1], &far = positions[edge.far];
    const glm::vec3 n0 = glm::cross(p1 - p0, third - p0);
    const glm::vec3 n1 = glm::cross(p0 - p1, far - p1);
    if (!has_area(n0) || !has_area(n1)) return FeatureEdge::none;
    const bool front0 = faces_eye(n0, p0, eye), front1 = faces_eye(n1, p1, eye);
    if (front0 != front1) {
        if (test.outline == Outline::silhouettes) return FeatureEdge::silhouette;
        if (test.outline == Outline::elsewhere) return FeatureEdge::none;
    }
    if (!test.creases || !(front0 || front1)) return FeatureEdge::none;
    if (glm::dot(glm::normalize(n0), glm::normalize(n1)) >= test.cos_crease) {
        return FeatureEdge::none;
    }
    return glm::dot(n0, far - p0) < 0.0f ? FeatureEdge::ridge : FeatureEdge::valley;
}

// Calls emit(edge_index, record, kind) for every edge of `records` that is a feature.
template <typename Emit>
void for_each_feature_edge(std::span<const EdgeRecord> records, const glm::vec3* positions,
                           const glm::vec3& eye, const FeatureTest& test, Emit&& emit) {
    for (uint32_t e = 0; e < records.size(); ++e) {
        const FeatureEdge kind = classify_edge(records[e], positions, eye, test);
        if (kind != FeatureEdge::none) emit(e, records[e], kind);
    }
}

struct ClassifiedEdge {
    uint32_t edge;  // index into EdgeTable::records
    FeatureEdge kind;
};

// The same into a list (cleared first), for reports and tests.
void find_feature_edges(std::span<const EdgeRecord> records, const glm::vec3* positions,
                        const glm::vec3& eye, const FeatureTest& test,
                        std::vector<ClassifiedEdge>& out);

}  // namespace nq::npr::adjacency

// EdgeChains: an entity's edges joined along chains, straight runs drawn as one edge.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "technical/edge_chains.h"

namespace nq::npr {
namespace {

using technical::ChainTolerance;
using technical::EdgeChains;
using technical::EdgeKind;
using technical::FoundEdge;

constexpr float kDepth = 100.0f;  // every test point lies this far in front of the eye
// One unit of world per pixel at kDepth.
constexpr ChainTolerance kHalfPixel{0.5f, 1.0f / kDepth};

// Vertices in view space (depth -kDepth), each its own seam representative unless told otherwise.
struct Scene {
    std::vector<glm::vec3> view;
    std::vector<uint32_t> representative;
    std::vector<FoundEdge> edges;

    uint32_t point(float x, float y) {
        view.push_back({x, y, -kDepth});
        representative.push_back(static_cast<uint32_t>(representative.size()));
        return static_cast<uint32_t>(view.size() - 1);
    }
    // steps + 1 points `spacing` apart along x, the odd ones raised by `amplitude`.
    std::vector<uint32_t> zigzag(int steps, float spacing, float amplitude = 0.0f) {
        std::vector<uint32_t> points;
        for (int i = 0; i <= steps; ++i)
            points.push_back(point(spacing * i, i % 2 ? amplitude : 0.0f));
        return points;
    }
    // A polyline through the points, one edge per step.
    void polyline(const std::vector<uint32_t>& points, EdgeKind kind = EdgeKind::silhouette) {
        for (size_t i = 0; i + 1 < points.size(); ++i) {
            edges.push_back({points[i], points[i + 1], kind});
        }
    }
    void simplify(const ChainTolerance& tolerance = kHalfPixel) {
        EdgeChains chains;
        chains.simplify(edges, representative, view.data(), tolerance);
    }
};

float distance_to_segment(glm::vec3 p, glm::vec3 a, glm::vec3 b) {
    const glm::vec3 ab = b - a;
    const float t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0f, 1.0f);
    return glm::length(a + t * ab - p);
}

// Every input vertex lies within `limit` of some output edge.
void expect_covered(const Scene& scene, const std::vector<uint32_t>& vertices, float limit) {
    for (uint32_t v : vertices) {
        float best = 1e9f;
        for (const FoundEdge& e : scene.edges) {
            best = std::min(best,
                            distance_to_segment(scene.view[v], scene.view[e.v0], scene.view[e.v1]));
        }
        EXPECT_LE(best, limit) << "vertex " << v;
    }
}

TEST(EdgeChains, AStraightChainBecomesOneEdgeBetweenItsEnds) {
    Scene s;
    const std::vector<uint32_t> line = s.zigzag(10, 3.0f);
    s.polyline(line);
    s.simplify();
    ASSERT_EQ(s.edges.size(), 1u);
    const std::set<uint32_t> ends{s.edges[0].v0, s.edges[0].v1};
    EXPECT_EQ(ends, (std::set<uint32_t>{line.front(), line.back()}));
    EXPECT_EQ(s.edges[0].kind, EdgeKind::silhouette);
}

TEST(EdgeChains, BendsOfMoreThanTheToleranceStay) {
    // A zigzag of 2-unit (2-pixel) amplitude: no run is straight within half a pixel.
    Scene s;
    const std::vector<uint32_t> zigzag = s.zigzag(8, 4.0f, 2.0f);
    s.polyline(zigzag);
    s.simplify();
    EXPECT_EQ(s.edges.size(), 8u);
}

TEST(EdgeChains, SmallWobblesAreMergedWithinTheTolerance) {
    // A 0.3-pixel wobble: merged, and every vertex stays within half a pixel of the result.
    Scene s;
    const std::vector<uint32_t> wobble = s.zigzag(12, 2.0f, 0.3f);
    s.polyline(wobble);
    s.simplify();
    EXPECT_LT(s.edges.size(), 3u);
    expect_covered(s, wobble, 0.5f);
}

TEST(EdgeChains, ToleranceScalesWithDepth) {
    // The same 2-unit zigzag ten times as far away is a fifth of a pixel: one edge.
    Scene s;
    const std::vector<uint32_t> zigzag = s.zigzag(8, 4.0f, 2.0f);
    for (glm::vec3& p : s.view) p.z *= 10.0f;
    s.polyline(zigzag);
    s.simplify();
    EXPECT_EQ(s.edges.size(), 1u);
}

TEST(EdgeChains, ChainsEndWhereThreeEdgesMeet) {
    // Three straight arms of three edges each from one centre: three edges, one per arm.
    Scene s;
    const uint32_t centre = s.point(0.0f, 0.0f);
    for (const glm::vec2 direction : {glm::vec2(1, 0), glm::vec2(-1, 0), glm::vec2(0, 1)}) {
        std::vector<uint32_t> arm{centre};
        for (int i = 1; i <= 3; ++i)
            arm.push_back(s.point(5.0f * i * direction.x, 5.0f * i * direction.y));
        s.polyline(arm);
    }
    s.simplify();
    EXPECT_EQ(s.edges.size(), 3u);
}

TEST(EdgeChains, KindsAreNeverJoined) {
    Scene s;
    const std::vector<uint32_t> line = s.zigzag(6, 3.0f);
    s.polyline({line[0], line[1], line[2], line[3]}, EdgeKind::ridge);
    s.polyline({line[3], line[4], line[5], line[6]}, EdgeKind::silhouette);
    s.simplify();
    ASSERT_EQ(s.edges.size(), 2u);
    EXPECT_NE(s.edges[0].kind, s.edges[1].kind);
}

TEST(EdgeChains, SkinSeamsDoNotBreakAChain) {
    // The chain passes a seam: two MDL vertices at one representative position.
    Scene s;
    const uint32_t a = s.point(0, 0), b = s.point(4, 0), c = s.point(8, 0);
    const uint32_t c_seam = s.point(8, 0), d = s.point(12, 0), e = s.point(16, 0);
    s.representative[c_seam] = s.representative[c];
    s.polyline({a, b, c});
    s.polyline({c_seam, d, e});
    s.simplify();
    ASSERT_EQ(s.edges.size(), 1u);
}

TEST(EdgeChains, ClosedLoopsKeepTheirCorners) {
    // A square, each side three edges: its corners stay, so four or five edges (a side may be
    // split where the walk starts) cover every vertex exactly.
    Scene s;
    std::vector<uint32_t> loop;
    const glm::vec2 corners[4] = {{0, 0}, {12, 0}, {12, 12}, {0, 12}};
    for (int side = 0; side < 4; ++side) {
        const glm::vec2 from = corners[side], to = corners[(side + 1) % 4];
        for (int i = 0; i < 3; ++i) {
            const glm::vec2 p = from + (to - from) * (i / 3.0f);
            loop.push_back(s.point(p.x, p.y));
        }
    }
    std::vector<uint32_t> closed = loop;
    closed.push_back(loop.front());
    s.polyline(closed);
    s.simplify();
    EXPECT_GE(s.edges.size(), 4u);
    EXPECT_LE(s.edges.size(), 5u);
    expect_covered(s, loop, 1e-4f);
}

TEST(EdgeChains, NothingIsMergedWithoutATolerance) {
    Scene s;
    const std::vector<uint32_t> line = s.zigzag(5, 3.0f);
    s.polyline(line);
    s.simplify({0.0f, 1.0f / kDepth});
    EXPECT_EQ(s.edges.size(), 5u);
}

TEST(EdgeChains, VerticesAtOrBehindTheEyeAreKept) {
    Scene s;
    const std::vector<uint32_t> line = s.zigzag(4, 3.0f);
    s.view[line[2]].z = 1.0f;  // behind the eye (GL view space looks down -z)
    s.polyline(line);
    s.simplify();
    EXPECT_EQ(s.edges.size(), 4u);
}

}  // namespace
}  // namespace nq::npr

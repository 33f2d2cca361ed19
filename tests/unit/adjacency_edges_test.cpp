// Edge data for renderers on shapes with known answers: the cube's 12 ridges, the L-step's one
// valley, a hinge folding both ways, a sphere's silhouette loop from a given eye (and why the
// eye test needs the plane's distance), the GL_TRIANGLES_ADJACENCY buffer, the verdict and the
// per-model cache that logs it once.
#include <gtest/gtest.h>

#include <map>
#include <numbers>
#include <set>
#include <string>

#include "adjacency/adjacency_cache.h"
#include "adjacency/edge_queries.h"
#include "adjacency_test_models.h"

namespace nq::npr::adjacency {
namespace {

using test::Packed;
using test::SyntheticAlias;

constexpr float kThirtyDegrees = std::numbers::pi_v<float> / 6;

// MDL-vertex pair of an edge (sorted), via each mesh vertex's MDL vertex.
std::pair<uint32_t, uint32_t> mdl_pair(const ModelAdjacency& a, uint32_t edge) {
    const MeshEdge& e = a.edges.edges[edge];
    const uint32_t x = a.mesh.vertex_mdl[e.v0], y = a.mesh.vertex_mdl[e.v1];
    return {std::min(x, y), std::max(x, y)};
}

TEST(AdjacencyCreases, CubeHasTwelveRidgesAndNoValleys) {
    SyntheticAlias cube = test::cube_model();
    const ModelAdjacency a = cube.recover();
    std::vector<uint32_t> ridges, valleys;
    find_creases(a.geometry, 0, kThirtyDegrees, ridges, valleys);
    EXPECT_EQ(ridges.size(), 12u);
    EXPECT_TRUE(valleys.empty());
    for (uint32_t e : ridges) {
        EXPECT_NEAR(a.geometry.signed_dihedral(0, e), std::numbers::pi / 2, 1e-6);
        // A cube edge joins corners differing in exactly one coordinate bit.
        const auto [x, y] = mdl_pair(a, e);
        EXPECT_EQ(std::popcount(x ^ y), 1) << x << "-" << y;
    }
    // The other six edges are the squares' diagonals: flat.
    size_t flat = 0;
    for (uint32_t e = 0; e < a.edges.edges.size(); ++e)
        flat += a.geometry.signed_dihedral(0, e) == 0;
    EXPECT_EQ(flat, 6u);
    // Outward unit normals: the -x square's plane is x = -10 facing -x.
    for (uint32_t f = 0; f < a.geometry.num_faces; ++f) {
        const FacePlane& p = a.geometry.plane(0, f);
        EXPECT_NEAR(glm::length(p.normal), 1.0f, 1e-6f);
        EXPECT_NEAR(p.distance, 10.0f, 1e-5f);  // every face is 10 from the centre, outward
    }
}

TEST(AdjacencyCreases, LStepHasOneValleyAtItsInnerCorner) {
    SyntheticAlias step = test::l_step_model();
    const ModelAdjacency a = step.recover();
    ASSERT_TRUE(a.problems.empty());
    EXPECT_EQ(a.stats.mesh.edges, 30u);
    EXPECT_EQ(a.stats.mesh.boundary, 0u);
    std::vector<uint32_t> ridges, valleys;
    find_creases(a.geometry, 0, kThirtyDegrees, ridges, valleys);
    // Convex: 6 profile edges on each cap, and the extrusion edges at 5 of the 6 corners.
    EXPECT_EQ(ridges.size(), 17u);
    ASSERT_EQ(valleys.size(), 1u);
    EXPECT_EQ(mdl_pair(a, valleys[0]), std::make_pair(3u, 9u));
    EXPECT_NEAR(a.geometry.signed_dihedral(0, valleys[0]), -std::numbers::pi / 2, 1e-6);
    EXPECT_EQ(classify_crease(a.geometry.signed_dihedral(0, valleys[0]), kThirtyDegrees),
              Crease::valley);
}

TEST(AdjacencyCreases, HingeFoldsIntoARidgeAndAValleyPerPose) {
    // Wing (0, 1, 2) fixed at z = 20, wing (3, 2, 1) flat in pose 0, its tip 3 folded down
    // 45 degrees in pose 1 (a roof: convex) and up in pose 2 (a trough: concave).
    const std::vector<Packed> flat{{0, 20, 20}, {20, 0, 20}, {20, 40, 20}, {40, 20, 20}};
    std::vector<Packed> down = flat, up = flat;
    down[3] = {40, 20, 0};
    up[3] = {40, 20, 40};
    SyntheticAlias hinge({flat, down, up});
    hinge.add_outward(0, 1, 2);
    hinge.add_outward(3, 2, 1);
    const ModelAdjacency a = hinge.recover();
    ASSERT_EQ(a.stats.mesh.manifold, 1u);
    uint32_t shared = 0;
    while (a.edges.edges[shared].boundary()) ++shared;
    EXPECT_EQ(a.geometry.signed_dihedral(0, shared), 0.0f);
    EXPECT_NEAR(a.geometry.signed_dihedral(1, shared), std::numbers::pi / 4, 1e-6);
    EXPECT_NEAR(a.geometry.signed_dihedral(2, shared), -std::numbers::pi / 4, 1e-6);
    EXPECT_EQ(classify_crease(a.geometry.signed_dihedral(1, shared), kThirtyDegrees),
              Crease::ridge);
    EXPECT_EQ(classify_crease(a.geometry.signed_dihedral(2, shared), kThirtyDegrees),
              Crease::valley);
    EXPECT_EQ(classify_crease(a.geometry.signed_dihedral(1, shared), std::numbers::pi_v<float> / 3),
              Crease::none);  // 45 degrees is below a 60 degree threshold
}

constexpr uint32_t kSlices = 16, kStacks = 8;

// Every vertex of the edge set has exactly two edges, and they form one closed loop.
bool is_single_loop(const std::vector<std::pair<uint32_t, uint32_t>>& edges) {
    std::map<uint32_t, std::vector<uint32_t>> next;
    for (const auto& [a, b] : edges) {
        next[a].push_back(b);
        next[b].push_back(a);
    }
    for (const auto& [v, n] : next) {
        if (n.size() != 2) return false;
    }
    uint32_t previous = next.begin()->first, at = next.begin()->second[0];
    size_t steps = 1;
    while (at != next.begin()->first && steps <= edges.size()) {
        const auto& n = next[at];
        const uint32_t following = n[0] == previous ? n[1] : n[0];
        previous = at;
        at = following;
        ++steps;
    }
    return steps == edges.size();
}

std::vector<std::pair<uint32_t, uint32_t>> silhouette(const ModelAdjacency& a, glm::vec3 eye) {
    std::vector<uint32_t> edges;
    find_silhouette_edges(a.edges, a.geometry, 0, eye, edges);
    std::vector<std::pair<uint32_t, uint32_t>> pairs;
    for (uint32_t e : edges) pairs.push_back(mdl_pair(a, e));
    return pairs;
}

TEST(AdjacencySilhouettes, SphereSeenFromAboveOutlinesTheEquator) {
    SyntheticAlias sphere = test::sphere_model(kSlices, kStacks, glm::vec3(-128));
    const ModelAdjacency a = sphere.recover();
    ASSERT_TRUE(a.problems.empty());
    EXPECT_EQ(a.stats.mesh.boundary, 0u);
    const auto edges = silhouette(a, glm::vec3(0, 0, 1000));
    ASSERT_EQ(edges.size(), kSlices);
    std::set<std::pair<uint32_t, uint32_t>> equator;
    for (uint32_t s = 0; s < kSlices; ++s) {
        const uint32_t x = test::sphere_vertex(kStacks / 2, s, kSlices, kStacks);
        const uint32_t y = test::sphere_vertex(kStacks / 2, s + 1, kSlices, kStacks);
        equator.insert({std::min(x, y), std::max(x, y)});
    }
    EXPECT_EQ(std::set(edges.begin(), edges.end()), equator);
    EXPECT_TRUE(is_single_loop(edges));
}

TEST(AdjacencySilhouettes, SphereSeenFromTheSideOutlinesTwoMeridians) {
    SyntheticAlias sphere = test::sphere_model(kSlices, kStacks, glm::vec3(-128));
    const ModelAdjacency a = sphere.recover();
    const auto edges = silhouette(a, glm::vec3(1e5f, 0, 0));
    // Longitudes 90 and 270 degrees, pole to pole.
    std::set<std::pair<uint32_t, uint32_t>> meridians;
    for (uint32_t slice : {kSlices / 4, 3 * kSlices / 4}) {
        for (uint32_t r = 0; r < kStacks; ++r) {
            const uint32_t x = test::sphere_vertex(r, slice, kSlices, kStacks);
            const uint32_t y = test::sphere_vertex(r + 1, slice, kSlices, kStacks);
            meridians.insert({std::min(x, y), std::max(x, y)});
        }
    }
    EXPECT_EQ(std::set(edges.begin(), edges.end()), meridians);
    EXPECT_EQ(edges.size(), 2 * kStacks);
    EXPECT_TRUE(is_single_loop(edges));
}

TEST(AdjacencySilhouettes, OffCentreSphereNeedsThePlaneDistance) {
    // The same sphere centred at (300, 0, 0), eye 1000 above its centre.
    SyntheticAlias sphere = test::sphere_model(kSlices, kStacks, glm::vec3(172, -128, -128));
    const ModelAdjacency a = sphere.recover();
    const glm::vec3 eye(300, 0, 1000);
    const auto edges = silhouette(a, eye);
    EXPECT_EQ(edges.size(), kSlices);
    EXPECT_TRUE(is_single_loop(edges));
    // (n0.e)(n1.e) <= 0 without the planes' distances picks other edges.
    size_t naive = 0, naive_on_equator = 0;
    for (uint32_t e = 0; e < a.edges.edges.size(); ++e) {
        const MeshEdge& edge = a.edges.edges[e];
        const float h0 = glm::dot(a.geometry.plane(0, edge.face0).normal, eye);
        const float h1 = glm::dot(a.geometry.plane(0, edge.face1).normal, eye);
        if (h0 * h1 > 0) continue;
        ++naive;
        naive_on_equator += std::count(edges.begin(), edges.end(), mdl_pair(a, e)) > 0;
    }
    EXPECT_GT(naive, 0u);
    EXPECT_LT(naive_on_equator, kSlices);
}

TEST(AdjacencySilhouettes, BlendedPosesMatchTheirEndsAndBoundariesAlwaysShow) {
    const std::vector<Packed> flat{{0, 20, 20}, {20, 0, 20}, {20, 40, 20}, {40, 20, 20}};
    std::vector<Packed> down = flat;
    down[3] = {40, 20, 0};
    SyntheticAlias hinge({flat, down});
    hinge.add_outward(0, 1, 2);
    hinge.add_outward(3, 2, 1);
    const ModelAdjacency a = hinge.recover();
    // From far out on the left wing's side, above it: flat, the sheet shows its top and the
    // hinge is no silhouette; folded down, the right wing faces away and the hinge is one.
    const glm::vec3 eye(-1000, 20, 500);
    std::vector<uint32_t> at0, at1, blended0, blended1;
    find_silhouette_edges(a.edges, a.geometry, 0, eye, at0);
    find_silhouette_edges(a.edges, a.geometry, 1, eye, at1);
    EXPECT_EQ(at0.size(), 4u);  // the four boundary edges only
    EXPECT_EQ(at1.size(), 5u);  // and the hinge
    find_silhouette_edges_blended(a.edges, a.geometry, 0, 1, 0.0f, eye, blended0);
    EXPECT_EQ(blended0, at0);
    find_silhouette_edges_blended(a.edges, a.geometry, 0, 1, 1.0f, eye, blended1);
    EXPECT_EQ(blended1, at1);
}

TEST(AdjacencyEdgeTable, TrianglesAdjacencyNamesEachNeighboursFarCorner) {
    SyntheticAlias cube = test::cube_model(true);  // seams: indices are MDL vertices
    const ModelAdjacency a = cube.recover();
    const auto& adj = a.edges.triangles_adjacency;
    ASSERT_EQ(adj.size(), 6u * 12);
    for (uint32_t f = 0; f < 12; ++f) {
        for (int k = 0; k < 3; ++k) {
            EXPECT_EQ(adj[6 * f + 2 * k], a.mesh.face_corners[f][k]);  // the face's own corners
            // The far corner of the neighbour across edge k: a corner of some other face of the
            // mesh that also holds this edge's two positions.
            const uint32_t across = a.mdl_to_mesh_vertex[adj[6 * f + 2 * k + 1]];
            const uint32_t u = a.mesh.face_vertices[f][k], w = a.mesh.face_vertices[f][(k + 1) % 3];
            bool found = false;
            for (uint32_t g = 0; g < 12; ++g) {
                const auto& fv = a.mesh.face_vertices[g];
                const std::set<uint32_t> s(fv.begin(), fv.end());
                found |= g != f && s == std::set<uint32_t>{u, w, across};
            }
            EXPECT_TRUE(found) << "face " << f << " edge " << k;
        }
    }
    // Edge lines: 2 MDL vertices per edge, at the edge's ends.
    ASSERT_EQ(a.edges.edge_lines.size(), 2 * a.edges.edges.size());
    for (size_t e = 0; e < a.edges.edges.size(); ++e) {
        EXPECT_EQ(a.mdl_to_mesh_vertex[a.edges.edge_lines[2 * e]], a.edges.edges[e].v0);
        EXPECT_EQ(a.mdl_to_mesh_vertex[a.edges.edge_lines[2 * e + 1]], a.edges.edges[e].v1);
    }
}

TEST(AdjacencyEdgeTable, BoundaryEdgesPointAtTheFacesOwnThirdCorner) {
    SyntheticAlias sheet({{{0, 0, 0}, {20, 0, 0}, {20, 20, 0}, {0, 20, 0}}});
    sheet.add_outward_quad(0, 1, 2, 3);
    const ModelAdjacency a = sheet.recover();
    EXPECT_EQ(a.edges.boundary_edges(), 4u);
    const auto& adj = a.edges.triangles_adjacency;
    size_t own = 0;
    for (uint32_t f = 0; f < 2; ++f) {
        for (int k = 0; k < 3; ++k)
            own += adj[6 * f + 2 * k + 1] == a.mesh.face_corners[f][(k + 2) % 3];
    }
    EXPECT_EQ(own, 4u);  // the other two "across" entries see the other triangle
    for (uint32_t f = 0; f < 2; ++f) {
        for (int k = 0; k < 3; ++k) {
            const uint32_t e = a.edges.face_edges[f][k];
            EXPECT_TRUE(a.edges.edges[e].face0 == f || a.edges.edges[e].face1 == f);
        }
    }
}

TEST(AdjacencyVerdict, ClosedShapesGetTrueEdgesOpenSheetsBackFaceLines) {
    SyntheticAlias cube = test::cube_model();
    const ModelAdjacency closed = cube.recover();
    EXPECT_EQ(closed.verdict.style, EdgeStyle::true_edges);
    EXPECT_EQ(closed.verdict.reason,
              "100.0% of 18 edges manifold and consistently oriented, 0 boundary");
    SyntheticAlias sheet({{{0, 0, 0}, {20, 0, 0}, {20, 20, 0}, {0, 20, 0}}});
    sheet.add_outward_quad(0, 1, 2, 3);
    const ModelAdjacency open = sheet.recover();
    EXPECT_EQ(open.verdict.style, EdgeStyle::backface_lines);
    EXPECT_EQ(open.verdict.reason,
              "20.0% of 5 edges manifold and consistently oriented, 4 boundary (below 95.0%)");
    // The threshold is a parameter: a lax one accepts the sheet.
    EXPECT_EQ(recover_adjacency(sheet.view(), 0.2).verdict.style, EdgeStyle::true_edges);
    RecoveryStats stats = closed.stats;
    EXPECT_EQ(judge_adjacency(stats, {"vertex 3 is not manifold"}).reason,
              "mesh check failed: vertex 3 is not manifold");
    stats.mesh.non_manifold = 2;
    EXPECT_EQ(judge_adjacency(stats, {}).reason, "2 non-manifold edges remain");
}

std::vector<std::string> g_log;
void record_log(int level, const char* text) {
    g_log.push_back(std::to_string(level) + " " + text);
}

TEST(AdjacencyCache, BuildsAndLogsOncePerModel) {
    g_log.clear();
    SyntheticAlias cube = test::cube_model();
    AdjacencyCache cache(record_log);
    const ModelAdjacency& first = cache.get(7, "progs/cube.mdl", cube.view());
    const ModelAdjacency& again = cache.get(7, "progs/cube.mdl", cube.view());
    EXPECT_EQ(&first, &again);
    EXPECT_EQ(cache.find(7), &first);
    EXPECT_EQ(cache.find(8), nullptr);
    ASSERT_EQ(g_log.size(), 1u);
    EXPECT_EQ(g_log[0],
              "0 adjacency: progs/cube.mdl: true silhouettes and creases (100.0% of 18 "
              "edges manifold and consistently oriented, 0 boundary)");
    cache.release(7);
    EXPECT_EQ(cache.size(), 0u);
    cache.get(7, "progs/cube.mdl", cube.view());
    EXPECT_EQ(g_log.size(), 2u);
}

}  // namespace
}  // namespace nq::npr::adjacency

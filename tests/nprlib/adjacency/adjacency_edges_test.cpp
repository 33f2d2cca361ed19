// Edge data for renderers on shapes with known answers, through the per-frame test the
// technical style draws with (feature_edges.h: classify_edge on a pose's positions and an eye):
// the cube's 12 ridges, the L-step's one valley, a hinge folding both ways, a sphere's
// silhouette loop from a given eye (and why the eye test needs the plane's distance), blended
// poses, the edge records' corners, the file's triangles with their twins and seam
// representatives, and the verdict. Per-pose planes and dihedrals (asked for) agree.
#include <gtest/gtest.h>

#include <map>
#include <numbers>
#include <set>
#include <string>

#include "adjacency/feature_edges.h"
#include "adjacency_test_models.h"

namespace nq::npr::adjacency {
namespace {

using test::Packed;
using test::SyntheticAlias;

constexpr RecoveryOptions kWithPoseGeometry{kMinManifoldShare, true};

// MDL-vertex pair of an edge (sorted), via each mesh vertex's MDL vertex.
std::pair<uint32_t, uint32_t> mdl_pair(const ModelAdjacency& a, uint32_t edge) {
    const MeshEdge& e = a.edges.edges[edge];
    const uint32_t x = a.mesh.vertex_mdl[e.v0], y = a.mesh.vertex_mdl[e.v1];
    return {std::min(x, y), std::max(x, y)};
}

FeatureTest creases_only(float degrees) {
    FeatureTest test;
    test.outline = Outline::ignored;
    test.cos_crease = crease_cosine(degrees);
    return test;
}

// Edge index -> kind, over eyes far out along the 26 axis and diagonal directions from
// `centre` (every edge of a convex-ish shape has a face seen from one of them). A kind must not
// change with the eye: creases depend on the shape alone.
std::map<uint32_t, FeatureEdge> creases_from_all_around(const ModelAdjacency& a,
                                                        const std::vector<glm::vec3>& pose,
                                                        glm::vec3 centre, float degrees) {
    std::map<uint32_t, FeatureEdge> kinds;
    std::vector<ClassifiedEdge> found;
    for (int x = -1; x <= 1; ++x) {
        for (int y = -1; y <= 1; ++y) {
            for (int z = -1; z <= 1; ++z) {
                if (x == 0 && y == 0 && z == 0) continue;
                const glm::vec3 eye = centre + 1000.0f * glm::vec3(x, y, z);
                find_feature_edges(a.edges.records, pose.data(), eye, creases_only(degrees), found);
                for (const ClassifiedEdge& e : found) {
                    const auto [it, fresh] = kinds.emplace(e.edge, e.kind);
                    EXPECT_EQ(it->second, e.kind) << "edge " << e.edge << " changed kind";
                }
            }
        }
    }
    return kinds;
}

size_t count_kind(const std::map<uint32_t, FeatureEdge>& kinds, FeatureEdge kind) {
    size_t n = 0;
    for (const auto& [edge, k] : kinds) n += k == kind;
    return n;
}

TEST(AdjacencyCreases, CubeHasTwelveRidgesAndNoValleys) {
    SyntheticAlias cube = test::cube_model();
    const ModelAdjacency a = cube.recover(kWithPoseGeometry);
    const auto kinds = creases_from_all_around(a, cube.positions(0), glm::vec3(0), 30.0f);
    EXPECT_EQ(count_kind(kinds, FeatureEdge::ridge), 12u);
    EXPECT_EQ(kinds.size(), 12u);  // no valley, and the 6 face diagonals are flat
    for (const auto& [e, kind] : kinds) {
        EXPECT_NEAR(a.geometry.signed_dihedral(0, e), std::numbers::pi / 2, 1e-6);
        // A cube edge joins corners differing in exactly one coordinate bit.
        const auto [x, y] = mdl_pair(a, e);
        EXPECT_EQ(std::popcount(x ^ y), 1) << x << "-" << y;
    }
    // Above 90 degrees nothing is a crease.
    EXPECT_TRUE(creases_from_all_around(a, cube.positions(0), glm::vec3(0), 100.0f).empty());
    // Outward unit normals: every face's plane is 10 from the centre.
    for (uint32_t f = 0; f < a.geometry.num_faces; ++f) {
        const FacePlane& p = a.geometry.plane(0, f);
        EXPECT_NEAR(glm::length(p.normal), 1.0f, 1e-6f);
        EXPECT_NEAR(p.distance, 10.0f, 1e-5f);
    }
}

TEST(AdjacencyCreases, CubeFromACornerShowsThreeRidgesInsideSixSilhouettes) {
    // Eye along (+x, +y, +z): three faces seen. Their three shared box edges are ridges, the six
    // edges between a seen and a hidden face the outline, the three between hidden faces nothing.
    SyntheticAlias cube = test::cube_model();
    const ModelAdjacency a = cube.recover();
    const std::vector<glm::vec3> pose = cube.positions(0);
    const glm::vec3 eye(1000, 700, 400);
    std::vector<ClassifiedEdge> found;
    find_feature_edges(a.edges.records, pose.data(), eye, FeatureTest{}, found);
    std::map<FeatureEdge, int> count;
    for (const ClassifiedEdge& e : found) ++count[e.kind];
    EXPECT_EQ(count[FeatureEdge::silhouette], 6);
    EXPECT_EQ(count[FeatureEdge::ridge], 3);
    EXPECT_EQ(found.size(), 9u);
    // With the outline drawn by another technique those six are nothing; with no outline at
    // all they turn by 90 degrees, so they are ridges.
    FeatureTest elsewhere;
    elsewhere.outline = Outline::elsewhere;
    find_feature_edges(a.edges.records, pose.data(), eye, elsewhere, found);
    EXPECT_EQ(found.size(), 3u);
    find_feature_edges(a.edges.records, pose.data(), eye, creases_only(60.0f), found);
    EXPECT_EQ(found.size(), 9u);
    for (const ClassifiedEdge& e : found) EXPECT_EQ(e.kind, FeatureEdge::ridge);
}

TEST(AdjacencyCreases, LStepHasOneValleyAtItsInnerCorner) {
    SyntheticAlias step = test::l_step_model();
    const ModelAdjacency a = step.recover(kWithPoseGeometry);
    ASSERT_TRUE(a.problems.empty());
    EXPECT_EQ(a.stats.mesh.edges, 30u);
    EXPECT_EQ(a.stats.mesh.boundary, 0u);
    const auto kinds = creases_from_all_around(a, step.positions(0), glm::vec3(15, 10, 15), 30.0f);
    // Convex: 6 profile edges on each cap, and the extrusion edges at 5 of the 6 corners.
    EXPECT_EQ(count_kind(kinds, FeatureEdge::ridge), 17u);
    ASSERT_EQ(count_kind(kinds, FeatureEdge::valley), 1u);
    for (const auto& [e, kind] : kinds) {
        if (kind != FeatureEdge::valley) continue;
        EXPECT_EQ(mdl_pair(a, e), std::make_pair(3u, 9u));
        EXPECT_NEAR(a.geometry.signed_dihedral(0, e), -std::numbers::pi / 2, 1e-6);
    }
}

// Wing (0, 1, 2) fixed at z = 20, wing (3, 2, 1) flat in pose 0, its tip 3 folded down 45
// degrees in pose 1 (a roof: convex) and up in pose 2 (a trough: concave).
SyntheticAlias hinge_model() {
    const std::vector<Packed> flat{{0, 20, 20}, {20, 0, 20}, {20, 40, 20}, {40, 20, 20}};
    std::vector<Packed> down = flat, up = flat;
    down[3] = {40, 20, 0};
    up[3] = {40, 20, 40};
    SyntheticAlias hinge({flat, down, up});
    hinge.add_outward(0, 1, 2);
    hinge.add_outward(3, 2, 1);
    return hinge;
}

// The kind of the hinge's one shared edge in `pose`, seen from high above.
FeatureEdge hinge_kind(SyntheticAlias& hinge, const ModelAdjacency& a, uint32_t pose,
                       float degrees) {
    uint32_t shared = 0;
    while (a.edges.edges[shared].boundary()) ++shared;
    const std::vector<glm::vec3> positions = hinge.positions(pose);
    return classify_edge(a.edges.records[shared], positions.data(), glm::vec3(20, 20, 1000),
                         creases_only(degrees));
}

TEST(AdjacencyCreases, HingeFoldsIntoARidgeAndAValleyPerPose) {
    SyntheticAlias hinge = hinge_model();
    const ModelAdjacency a = hinge.recover(kWithPoseGeometry);
    ASSERT_EQ(a.stats.mesh.manifold, 1u);
    EXPECT_EQ(hinge_kind(hinge, a, 0, 30.0f), FeatureEdge::none);
    EXPECT_EQ(hinge_kind(hinge, a, 1, 30.0f), FeatureEdge::ridge);
    EXPECT_EQ(hinge_kind(hinge, a, 2, 30.0f), FeatureEdge::valley);
    EXPECT_EQ(hinge_kind(hinge, a, 1, 60.0f), FeatureEdge::none);  // 45 is below 60 degrees
    EXPECT_EQ(hinge_kind(hinge, a, 2, 44.0f), FeatureEdge::valley);
    // The pose geometry measures the same angles.
    uint32_t shared = 0;
    while (a.edges.edges[shared].boundary()) ++shared;
    EXPECT_EQ(a.geometry.signed_dihedral(0, shared), 0.0f);
    EXPECT_NEAR(a.geometry.signed_dihedral(1, shared), std::numbers::pi / 4, 1e-6);
    EXPECT_NEAR(a.geometry.signed_dihedral(2, shared), -std::numbers::pi / 4, 1e-6);
}

TEST(AdjacencyCreases, PoseGeometryIsOnlyComputedWhenAskedFor) {
    SyntheticAlias hinge = hinge_model();
    EXPECT_TRUE(hinge.recover().geometry.planes.empty());
    const ModelAdjacency a = hinge.recover(kWithPoseGeometry);
    EXPECT_EQ(a.geometry.planes.size(), 3u * 2);
    EXPECT_EQ(a.geometry.dihedral.size(), 3u * 5);
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

// Silhouette and border edges of pose 0 seen from `eye`, as MDL vertex pairs.
std::vector<std::pair<uint32_t, uint32_t>> silhouette(SyntheticAlias& model,
                                                      const ModelAdjacency& a, glm::vec3 eye) {
    const std::vector<glm::vec3> pose = model.positions(0);
    FeatureTest outline;
    outline.creases = false;
    std::vector<ClassifiedEdge> edges;
    find_feature_edges(a.edges.records, pose.data(), eye, outline, edges);
    std::vector<std::pair<uint32_t, uint32_t>> pairs;
    for (const ClassifiedEdge& e : edges) pairs.push_back(mdl_pair(a, e.edge));
    return pairs;
}

TEST(AdjacencySilhouettes, SphereSeenFromAboveOutlinesTheEquator) {
    SyntheticAlias sphere = test::sphere_model(kSlices, kStacks, glm::vec3(-128));
    const ModelAdjacency a = sphere.recover();
    ASSERT_TRUE(a.problems.empty());
    EXPECT_EQ(a.stats.mesh.boundary, 0u);
    const auto edges = silhouette(sphere, a, glm::vec3(0, 0, 1000));
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
    const auto edges = silhouette(sphere, a, glm::vec3(1e5f, 0, 0));
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
    const ModelAdjacency a = sphere.recover(kWithPoseGeometry);
    const glm::vec3 eye(300, 0, 1000);
    const auto edges = silhouette(sphere, a, eye);
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

TEST(AdjacencySilhouettes, BlendedPosesMoveTheOutlineAndBordersAlwaysShow) {
    const std::vector<Packed> flat{{0, 20, 20}, {20, 0, 20}, {20, 40, 20}, {40, 20, 20}};
    std::vector<Packed> down = flat;
    down[3] = {40, 20, 0};
    SyntheticAlias hinge({flat, down});
    hinge.add_outward(0, 1, 2);
    hinge.add_outward(3, 2, 1);
    const ModelAdjacency a = hinge.recover();
    const std::vector<glm::vec3> pose0 = hinge.positions(0), pose1 = hinge.positions(1);
    // From far out on the left wing's side, above it: flat, the sheet shows its top and the
    // hinge is no silhouette; folded down, the right wing faces away and the hinge is one. The
    // right wing's normal is (s, 0, 1) for a slope s = lerp, so it turns away from this eye
    // (direction (-1030, 0, 485) from the wing) once s > 485 / 1030 = 0.47.
    const glm::vec3 eye(-1000, 20, 500);
    std::vector<glm::vec3> blended(pose0.size());
    std::vector<ClassifiedEdge> found;
    for (const auto& [lerp, expected] :
         std::vector<std::pair<float, size_t>>{{0.0f, 4}, {0.4f, 4}, {0.55f, 5}, {1.0f, 5}}) {
        for (size_t v = 0; v < blended.size(); ++v) {
            blended[v] = pose0[v] * (1.0f - lerp) + pose1[v] * lerp;
        }
        find_feature_edges(a.edges.records, blended.data(), eye, FeatureTest{}, found);
        EXPECT_EQ(found.size(), expected) << "lerp " << lerp;
        size_t borders = 0;
        for (const ClassifiedEdge& e : found) borders += e.kind == FeatureEdge::border;
        EXPECT_EQ(borders, 4u);  // the four open borders, from any eye
    }
}

TEST(AdjacencyEdgeTable, RecordsNameBothFacesCornersCounterClockwiseFromOutside) {
    SyntheticAlias cube = test::cube_model(true);  // seams: a position has several MDL vertices
    const ModelAdjacency a = cube.recover();
    const std::vector<glm::vec3> p = cube.positions(0);
    ASSERT_EQ(a.edges.records.size(), a.edges.edges.size());
    ASSERT_EQ(a.edges.records.size(), 18u);
    // The same triangle (as positions), whatever corner it starts from.
    const auto same_triangle = [&](std::array<glm::vec3, 3> x, std::array<glm::vec3, 3> y) {
        for (int r = 0; r < 3; ++r) {
            if (x[0] == y[r] && x[1] == y[(r + 1) % 3] && x[2] == y[(r + 2) % 3]) return true;
        }
        return false;
    };
    const auto face = [&](uint32_t f) {
        const auto& c = a.mesh.face_corners[f];
        return std::array<glm::vec3, 3>{p[c[0]], p[c[1]], p[c[2]]};
    };
    for (uint32_t e = 0; e < a.edges.records.size(); ++e) {
        const EdgeRecord& r = a.edges.records[e];
        const MeshEdge& m = a.edges.edges[e];
        ASSERT_FALSE(r.border());
        EXPECT_TRUE(same_triangle({p[r.v0], p[r.v1], p[r.third]}, face(m.face0))) << e;
        EXPECT_TRUE(same_triangle({p[r.v1], p[r.v0], p[r.far]}, face(m.face1))) << e;
        // Counter-clockwise from outside: face0's normal points away from the cube's centre.
        const glm::vec3 n = glm::cross(p[r.v1] - p[r.v0], p[r.third] - p[r.v0]);
        EXPECT_GT(glm::dot(n, (p[r.v0] + p[r.v1] + p[r.third]) / 3.0f), 0.0f) << e;
    }
}

TEST(AdjacencyEdgeTable, BorderRecordsPointAtTheFacesOwnThirdCorner) {
    SyntheticAlias sheet({{{0, 0, 0}, {20, 0, 0}, {20, 20, 0}, {0, 20, 0}}});
    sheet.add_outward_quad(0, 1, 2, 3);
    const ModelAdjacency a = sheet.recover();
    EXPECT_EQ(a.edges.boundary_edges(), 4u);
    for (uint32_t e = 0; e < a.edges.records.size(); ++e) {
        EXPECT_EQ(a.edges.records[e].border(), a.edges.edges[e].boundary()) << e;
    }
}

TEST(AdjacencyFileTriangles, SeamsShareARepresentativeAndEverySideOfAClosedCubeHasItsTwin) {
    SyntheticAlias cube = test::cube_model(true);
    const ModelAdjacency a = cube.recover();
    const FileTriangles& file = a.file;
    ASSERT_EQ(file.triangles.size(), 12u);
    const std::vector<glm::vec3> p = cube.positions(0);
    // 24 MDL vertices on 8 corners: each vertex's representative is the lowest-numbered vertex
    // at the same position (found here by position).
    ASSERT_EQ(file.seam_representatives.size(), 24u);
    for (uint32_t v = 0; v < 24; ++v) {
        uint32_t lowest = v;
        for (uint32_t w = 0; w < v; ++w) {
            if (p[w] == p[v]) {
                lowest = w;
                break;
            }
        }
        EXPECT_EQ(file.seam_representatives[v], lowest) << v;
    }
    // Every side's twin runs the same two positions the other way.
    for (uint32_t t = 0; t < 12; ++t) {
        for (uint32_t k = 0; k < 3; ++k) {
            const int32_t twin = file.twins[t][k];
            ASSERT_GE(twin, 0) << t << " " << k;
            const glm::vec3 a0 = p[file.triangles[t][k]], a1 = p[file.triangles[t][(k + 1) % 3]];
            bool reversed = false;
            for (uint32_t j = 0; j < 3; ++j) {
                reversed |=
                    p[file.triangles[twin][j]] == a1 && p[file.triangles[twin][(j + 1) % 3]] == a0;
            }
            EXPECT_TRUE(reversed) << t << " " << k;
        }
    }
    // The sheet's outer sides have none; its diagonal has one.
    SyntheticAlias sheet({{{0, 0, 0}, {20, 0, 0}, {20, 20, 0}, {0, 20, 0}}});
    sheet.add_outward_quad(0, 1, 2, 3);
    int twinned = 0;
    for (const auto& sides : sheet.recover().file.twins) {
        for (int32_t twin : sides) twinned += twin >= 0;
    }
    EXPECT_EQ(twinned, 2);
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
    EXPECT_EQ(sheet.recover({0.2}).verdict.style, EdgeStyle::true_edges);
    RecoveryStats stats = closed.stats;
    EXPECT_EQ(judge_adjacency(stats, {"vertex 3 is not manifold"}).reason,
              "mesh check failed: vertex 3 is not manifold");
    stats.mesh.non_manifold = 2;
    EXPECT_EQ(judge_adjacency(stats, {}).reason, "2 non-manifold edges remain");
}

}  // namespace
}  // namespace nq::npr::adjacency

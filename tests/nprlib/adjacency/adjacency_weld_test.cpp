// Welding, triangle filtering and the paper's per-frame hashing on small synthetic soups whose
// answers are known by construction: seam duplicates, parts that touch only in frame 0,
// (a,a,b)/(a,a,a) and zero-area degenerates, exact duplicates and back-to-back twins.
#include <gtest/gtest.h>

#include "adjacency/alias_source.h"
#include "adjacency/edge_census.h"
#include "adjacency/paper_baseline.h"
#include "adjacency/triangle_filter.h"
#include "adjacency/weld.h"
#include "adjacency_test_models.h"

namespace nq::npr::adjacency {
namespace {

using test::Packed;
using test::SyntheticAlias;

TEST(AdjacencyWeld, SeamDuplicatesOfACubeWeldToItsEightCorners) {
    SyntheticAlias cube = test::cube_model(/*seam_duplicates=*/true);
    const AliasSource source(cube.view());
    const VertexWeld weld = weld_coincident_vertices(source);
    ASSERT_EQ(weld.class_of.size(), 24u);
    EXPECT_EQ(weld.num_classes(), 8u);
    EXPECT_EQ(weld.merged(), 16u);
    // Vertex 4f+k sits at corner kCubeQuads[f][k]: same corner <=> same class.
    for (uint32_t a = 0; a < 24; ++a) {
        for (uint32_t b = 0; b < 24; ++b) {
            const bool same_corner =
                test::kCubeQuads[a / 4][a % 4] == test::kCubeQuads[b / 4][b % 4];
            EXPECT_EQ(weld.class_of[a] == weld.class_of[b], same_corner) << a << " " << b;
        }
        EXPECT_LE(weld.representative[weld.class_of[a]], a);  // the lowest index represents
    }
}

// Two triangles (0,1,2) and (3,4,5) sharing an edge's position in frame 0 only: 3 = 1 and
// 4 = 0 there; in frame 1 the second one has moved up. Vertex 6 coincides with 2 in both.
SyntheticAlias part_touching_in_frame0() {
    std::vector<Packed> frame0{{0, 0, 0}, {20, 0, 0},   {10, 20, 0}, {20, 0, 0},
                               {0, 0, 0}, {10, 250, 0}, {10, 20, 0}};
    std::vector<Packed> frame1 = frame0;
    frame1[3] = {20, 0, 30};
    frame1[4] = {0, 0, 30};
    frame1[5] = {10, 250, 30};
    SyntheticAlias model({frame0, frame1});
    model.add_stored(0, 1, 2);
    model.add_stored(3, 4, 5);
    model.add_stored(1, 0, 6);  // a back-to-back twin of the first, through its duplicate 6
    return model;
}

TEST(AdjacencyWeld, VerticesThatPartInALaterFrameAreNeverMerged) {
    SyntheticAlias model = part_touching_in_frame0();
    const AliasSource source(model.view());
    const VertexWeld weld = weld_coincident_vertices(source);
    EXPECT_EQ(weld.num_classes(), 6u);  // only 6 joins 2
    EXPECT_EQ(weld.class_of[6], weld.class_of[2]);
    EXPECT_NE(weld.class_of[3], weld.class_of[1]);
    EXPECT_NE(weld.class_of[4], weld.class_of[0]);
    // Judged on frame 0 alone, 3 and 4 would weld as well.
    const VertexWeld frame0 = weld_in_one_pose(source, 0);
    EXPECT_EQ(frame0.num_classes(), 4u);
    EXPECT_EQ(frame0.class_of[3], frame0.class_of[1]);

    const ModelAdjacency adjacency = model.recover();
    EXPECT_EQ(adjacency.stats.welds, 1u);
    EXPECT_EQ(adjacency.stats.kept_apart, 2u);
    EXPECT_EQ(adjacency.stats.removed.back_to_back_twins, 1u);
    // Two separate triangles: six boundary edges, nothing shared.
    EXPECT_EQ(adjacency.stats.mesh.edges, 6u);
    EXPECT_EQ(adjacency.stats.mesh.boundary, 6u);
    EXPECT_EQ(adjacency.stats.mesh_vertices, 6u);
    EXPECT_TRUE(adjacency.problems.empty());
}

TEST(AdjacencyPaperBaseline, FindsAnEdgeInFrame0ThatTearsInFrame1) {
    SyntheticAlias model = part_touching_in_frame0();
    const AliasSource source(model.view());
    // Frame 0 by positions: the twin's three edges coincide with triangle 0's (opposite
    // directions), and triangle 1's edge 3-4 lies on edge 0-1 too, so edge 0-1 has three uses.
    const EdgeCensus frame0 = hash_edges_in_pose(source, 0);
    EXPECT_EQ(frame0.edges, 5u);
    EXPECT_EQ(frame0.non_manifold, 1u);  // 0-1: triangle 0, its twin, triangle 1
    EXPECT_EQ(frame0.manifold, 2u);      // 1-2 and 2-0 with the twin
    EXPECT_EQ(frame0.consistent, 2u);
    EXPECT_EQ(frame0.boundary, 2u);  // triangle 1's other two edges
    const EdgeCensus frame1 = hash_edges_in_pose(source, 1);
    EXPECT_EQ(frame1.edges, 6u);
    EXPECT_EQ(frame1.manifold, 3u);  // triangle 0 with its twin
    EXPECT_EQ(frame1.boundary, 3u);
    const BaselineReport report = run_paper_baseline(source);
    EXPECT_EQ(report.poses, 2u);
    EXPECT_EQ(report.poses_unlike_first, 1u);
    EXPECT_EQ(report.first_pose, frame0);
    EXPECT_EQ(report.worst_pose_index, 0u);  // 2/5 consistent in frame 0, 3/6 in frame 1
}

TEST(AdjacencyPaperBaseline, JoinsSeamsByPositionButSeesTwinsAsNonManifold) {
    SyntheticAlias cube = test::cube_model(true);
    const EdgeCensus census = hash_edges_in_pose(AliasSource(cube.view()), 0);
    EXPECT_EQ(census.edges, 18u);
    EXPECT_EQ(census.consistent, 18u);

    // A quad a b c d (two triangles) and both triangles again reversed.
    SyntheticAlias sheet({{{0, 0, 0}, {20, 0, 0}, {20, 20, 0}, {0, 20, 0}}});
    sheet.add_outward_quad(0, 1, 2, 3);
    sheet.add_stored(0, 1, 2);
    sheet.add_stored(0, 2, 3);
    const EdgeCensus twins = hash_edges_in_pose(AliasSource(sheet.view()), 0);
    EXPECT_EQ(twins.edges, 5u);
    EXPECT_EQ(twins.non_manifold, 1u);  // the diagonal, used four times
    EXPECT_EQ(twins.manifold, 4u);      // each border edge, once per side
    EXPECT_EQ(twins.consistent, 4u);
    EXPECT_EQ(twins.boundary, 0u);
}

TEST(AdjacencyFilter, DegeneratesAreDroppedForTheRightReason) {
    // 0..3 a tetrahedron-ish set; 4 duplicates 0 in both frames; 5, 6 are collinear with 0 in
    // both frames; 7 is collinear with 0 and 1 in frame 0 only.
    std::vector<Packed> f0{{0, 0, 0}, {20, 0, 0},   {0, 20, 0},   {0, 0, 20},
                           {0, 0, 0}, {10, 10, 10}, {20, 20, 20}, {10, 0, 0}};
    std::vector<Packed> f1 = f0;
    for (Packed& p : f1) p[2] = uint8_t(p[2] + 5);  // the whole model moves up...
    f1[5] = {30, 30, 35};                           // ...and 5 slides along its line
    f1[7] = {10, 7, 5};                             // 7 leaves the line 0-1
    SyntheticAlias model({f0, f1});
    model.add_stored(0, 1, 2);  // kept
    model.add_stored(1, 1, 2);  // (a, a, b)
    model.add_stored(3, 3, 3);  // (a, a, a)
    model.add_stored(4, 0, 3);  // 4 and 0 coincide in every frame
    model.add_stored(0, 5, 6);  // collinear in every frame
    model.add_stored(0, 7, 1);  // flat in frame 0 only: kept
    model.add_stored(0, 9, 1);  // index out of range (a broken view)
    const AliasSource source(model.view());
    const FilteredTriangles filtered = filter_triangles(source, weld_coincident_vertices(source));
    const std::vector<TriangleFate> expected{
        TriangleFate::kept,           TriangleFate::repeated_index,
        TriangleFate::repeated_index, TriangleFate::collapsed_by_weld,
        TriangleFate::zero_area,      TriangleFate::kept,
        TriangleFate::bad_index};
    EXPECT_EQ(filtered.fate, expected);
    EXPECT_EQ(filtered.counts.repeated_index, 2u);
    EXPECT_EQ(filtered.counts.collapsed_by_weld, 1u);
    EXPECT_EQ(filtered.counts.zero_area, 1u);
    EXPECT_EQ(filtered.counts.degenerate(), 4u);
    EXPECT_EQ(filtered.counts.bad_index, 1u);
    ASSERT_EQ(filtered.kept.size(), 2u);
    EXPECT_EQ(filtered.kept[1].mdl_triangle, 5u);
    EXPECT_EQ(filtered.kept[1].mdl_vertices, (std::array<uint32_t, 3>{0, 7, 1}));
}

TEST(AdjacencyFilter, ZeroScaleAxisFlattensTriangles) {
    // A triangle in the x-z plane, but the model's z scale is 0: no area in model space.
    SyntheticAlias model({{{0, 0, 0}, {20, 0, 0}, {0, 0, 20}}}, glm::vec3(1, 1, 0));
    model.add_stored(0, 1, 2);
    const AliasSource source(model.view());
    EXPECT_EQ(filter_triangles(source, weld_coincident_vertices(source)).counts.zero_area, 1u);
}

TEST(AdjacencyFilter, DuplicatesAndBackToBackTwinsKeepTheFirst) {
    // Quad 0 1 2 3; 4 is a seam duplicate of 2.
    SyntheticAlias sheet({{{0, 0, 0}, {20, 0, 0}, {20, 20, 0}, {0, 20, 0}, {20, 20, 0}}});
    sheet.add_outward_quad(0, 1, 2, 3);  // triangles 0, 1
    sheet.add_stored(0, 1, 4);           // 2: twin of triangle 0 (through the duplicate)
    sheet.add_stored(2, 3, 0);           // 3: twin of triangle 1
    sheet.add_stored(3, 2, 0);           // 4: triangle 1 again, rotated: exact duplicate
    const AliasSource source(sheet.view());
    const FilteredTriangles filtered = filter_triangles(source, weld_coincident_vertices(source));
    EXPECT_EQ(filtered.fate[2], TriangleFate::back_to_back_twin);
    EXPECT_EQ(filtered.fate[3], TriangleFate::back_to_back_twin);
    EXPECT_EQ(filtered.fate[4], TriangleFate::exact_duplicate);
    EXPECT_EQ(filtered.counts.duplicates(), 3u);
    ASSERT_EQ(filtered.kept.size(), 2u);
    EXPECT_EQ(filtered.kept[0].mdl_triangle, 0u);
    EXPECT_EQ(filtered.kept[1].mdl_triangle, 1u);

    const ModelAdjacency adjacency = sheet.recover();
    EXPECT_EQ(adjacency.stats.mesh_faces, 2u);
    EXPECT_EQ(adjacency.stats.mesh.edges, 5u);
    EXPECT_EQ(adjacency.stats.mesh.boundary, 4u);
    EXPECT_EQ(adjacency.stats.mesh.consistent, 1u);
    EXPECT_TRUE(adjacency.problems.empty());
}

TEST(AdjacencyEdgeCensus, CountsUsesAndDirections) {
    const std::vector<std::array<uint32_t, 3>> triangles{{0, 1, 2}, {1, 0, 3}, {2, 1, 4},
                                                         {0, 2, 5}, {5, 2, 6}, {6, 2, 7}};
    // Edges used twice, each in opposite directions: 0-1, 1-2, 2-0, 2-5, 2-6. Used once:
    // 0-3, 1-3, 1-4, 2-4, 0-5, 5-6, 2-7, 6-7.
    const EdgeCensus c = census_of_indexed_triangles(triangles);
    EXPECT_EQ(c.edges, 13u);
    EXPECT_EQ(c.non_manifold, 0u);
    EXPECT_EQ(c.manifold, 5u);
    EXPECT_EQ(c.consistent, 5u);
    EXPECT_EQ(c.boundary, 8u);
    EXPECT_EQ(c.zero_length, 0u);
    EXPECT_DOUBLE_EQ(c.consistent_share(), 5.0 / 13.0);

    const std::vector<std::array<uint32_t, 3>> same_way{{0, 1, 2}, {0, 1, 3}, {0, 1, 4}};
    const EdgeCensus fin = census_of_indexed_triangles(same_way);
    EXPECT_EQ(fin.non_manifold, 1u);
    const std::vector<std::array<uint32_t, 3>> clash{{0, 1, 2}, {0, 1, 3}};
    const EdgeCensus inconsistent = census_of_indexed_triangles(clash);
    EXPECT_EQ(inconsistent.manifold, 1u);
    EXPECT_EQ(inconsistent.consistent, 0u);
    // (a, a, b): a zero-length edge a-a, and a-b traversed both ways.
    const std::vector<std::array<uint32_t, 3>> degenerate{{0, 0, 1}};
    const EdgeCensus flat = census_of_indexed_triangles(degenerate);
    EXPECT_EQ(flat.edges, 2u);
    EXPECT_EQ(flat.zero_length, 1u);
    EXPECT_EQ(flat.manifold, 1u);
}

}  // namespace
}  // namespace nq::npr::adjacency

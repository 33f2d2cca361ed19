// The OpenMesh half-edge mesh built from synthetic soups: closed shapes stay closed, seams
// weld, inconsistent faces are flipped, and every non-manifold configuration (three-triangle
// fin, closed fan touched at a vertex, Moebius strip) is split into a valid manifold mesh with
// the expected counts.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include <glm/geometric.hpp>

#include "adjacency/mesh_checks.h"
#include "adjacency/model_adjacency.h"
#include "adjacency_test_models.h"

namespace nq::npr::adjacency {
namespace {

using test::Packed;
using test::SyntheticAlias;

// 6 x signed volume of the mesh (pose-0 points): positive when faces wind outward.
double signed_volume6(const BuiltMesh& built) {
    double v = 0;
    for (const auto& f : built.face_vertices) {
        const auto p = [&](uint32_t i) {
            const auto q = built.mesh.point(OpenMesh::VertexHandle(int(i)));
            return glm::dvec3(q[0], q[1], q[2]);
        };
        v += glm::dot(p(f[0]), glm::cross(p(f[1]), p(f[2])));
    }
    return v;
}

void expect_openmesh_consistent(const TriMesh& mesh) {
    for (const auto v : mesh.vertices()) EXPECT_TRUE(mesh.is_manifold(v)) << v.idx();
    for (const auto h : mesh.halfedges()) {
        EXPECT_TRUE(mesh.opposite_halfedge_handle(h).is_valid());
        EXPECT_TRUE(mesh.next_halfedge_handle(h).is_valid());
        EXPECT_EQ(mesh.opposite_halfedge_handle(mesh.opposite_halfedge_handle(h)), h);
    }
}

TEST(AdjacencyMesh, CubeIsAClosedManifold) {
    SyntheticAlias cube = test::cube_model();
    const ModelAdjacency a = cube.recover();
    EXPECT_TRUE(a.problems.empty()) << a.problems.front();
    EXPECT_EQ(a.stats.mesh_vertices, 8u);
    EXPECT_EQ(a.stats.mesh_faces, 12u);
    EXPECT_EQ(a.stats.mesh.edges, 18u);  // V - E + F = 2
    EXPECT_EQ(a.stats.mesh.boundary, 0u);
    EXPECT_EQ(a.stats.mesh.consistent, 18u);
    EXPECT_EQ(a.stats.flipped_faces, 0u);
    EXPECT_EQ(a.stats.splits.new_vertices, 0u);
    EXPECT_DOUBLE_EQ(signed_volume6(a.mesh), 6.0 * 20 * 20 * 20);
    expect_openmesh_consistent(a.mesh.mesh);
    // Pose-0 points are model space: the cube is centred on the origin.
    const auto p = a.mesh.mesh.point(OpenMesh::VertexHandle(int(a.mdl_to_mesh_vertex[7])));
    EXPECT_EQ(glm::vec3(p[0], p[1], p[2]), glm::vec3(10, 10, 10));
}

TEST(AdjacencyMesh, SeamDuplicatesWeldButKeepTheirTextureCorners) {
    SyntheticAlias cube = test::cube_model(true);
    const ModelAdjacency a = cube.recover();
    EXPECT_TRUE(a.problems.empty());
    EXPECT_EQ(a.stats.welds, 16u);
    EXPECT_EQ(a.stats.mesh_vertices, 8u);
    EXPECT_EQ(a.stats.mesh.edges, 18u);
    EXPECT_EQ(a.stats.mesh.boundary, 0u);
    // The three MDL vertices at a corner map to one mesh vertex...
    for (uint32_t v = 0; v < 24; ++v) {
        const uint32_t corner = test::kCubeQuads[v / 4][v % 4];
        for (uint32_t w = 0; w < 24; ++w) {
            if (test::kCubeQuads[w / 4][w % 4] == corner) {
                EXPECT_EQ(a.mdl_to_mesh_vertex[v], a.mdl_to_mesh_vertex[w]);
            }
        }
    }
    // ...while each face keeps the MDL vertices (texture coordinates) of its own triangle.
    for (size_t f = 0; f < a.mesh.face_corners.size(); ++f) {
        const uint32_t quad = a.mesh.face_triangle[f] / 2;
        for (uint32_t corner : a.mesh.face_corners[f]) EXPECT_EQ(corner / 4, quad);
        for (int k = 0; k < 3; ++k) {
            EXPECT_EQ(a.mdl_to_mesh_vertex[a.mesh.face_corners[f][k]], a.mesh.face_vertices[f][k]);
        }
    }
}

TEST(AdjacencyMesh, FacesAgainstTheirNeighboursAreFlipped) {
    // The cube with its +z face (triangles 10, 11) stored the other way round.
    SyntheticAlias cube({[] {
        std::vector<Packed> v;
        for (uint32_t i = 0; i < 8; ++i) v.push_back(test::cube_corner(i));
        return v;
    }()});
    for (uint32_t f = 0; f < 6; ++f) {
        const auto& q = test::kCubeQuads[f];
        if (f == 5) {
            cube.add_outward_quad(q[3], q[2], q[1], q[0]);
        } else {
            cube.add_outward_quad(q[0], q[1], q[2], q[3]);
        }
    }
    const ModelAdjacency a = cube.recover();
    EXPECT_EQ(a.stats.soup.manifold, 18u);
    EXPECT_EQ(a.stats.soup.consistent, 18u - 4u);  // the flipped square's four sides
    EXPECT_EQ(a.stats.flipped_faces, 2u);          // the minority is flipped back
    EXPECT_EQ(a.stats.orientation_conflicts, 0u);
    EXPECT_EQ(a.stats.mesh.consistent, 18u);
    EXPECT_GT(signed_volume6(a.mesh), 0.0);
    size_t flipped = 0;
    for (size_t f = 0; f < a.mesh.face_flipped.size(); ++f) {
        if (a.mesh.face_flipped[f]) {
            ++flipped;
            EXPECT_GE(a.mesh.face_triangle[f], 10u);
        }
    }
    EXPECT_EQ(flipped, 2u);
    EXPECT_TRUE(a.problems.empty());
}

TEST(AdjacencyMesh, ThreeTriangleFinIsSplitOff) {
    // A flat sheet (0,1,2) + (1,0,3) and a fin (0,1,4) standing on the shared edge 0-1.
    SyntheticAlias fin({{{0, 20, 0}, {20, 20, 0}, {10, 40, 0}, {10, 0, 0}, {10, 20, 20}}});
    fin.add_stored(0, 1, 2);
    fin.add_stored(1, 0, 3);
    fin.add_stored(0, 1, 4);
    const ModelAdjacency a = fin.recover();
    EXPECT_EQ(a.stats.soup.non_manifold, 1u);
    EXPECT_EQ(a.stats.soup.edges, 7u);
    // The fin keeps only edge 0-1 in common with the sheet, so it becomes an island: one
    // copy for the blocked edge (complex edge), one for the fan it leaves at the other end.
    EXPECT_EQ(a.stats.splits.complex_edge_faces, 1u);
    EXPECT_EQ(a.stats.splits.fan_splits, 1u);
    EXPECT_EQ(a.stats.splits.new_vertices, 2u);
    EXPECT_EQ(a.stats.mesh_vertices, 7u);
    EXPECT_EQ(a.stats.mesh.non_manifold, 0u);
    EXPECT_EQ(a.stats.mesh.edges, 8u);
    EXPECT_EQ(a.stats.mesh.manifold, 1u);  // the sheet's edge
    EXPECT_EQ(a.stats.mesh.boundary, 7u);
    EXPECT_TRUE(a.problems.empty());
    expect_openmesh_consistent(a.mesh.mesh);
    // The fin's corners still name MDL vertices 0, 1 and 4.
    const size_t fin_face =
        std::find(a.mesh.face_triangle.begin(), a.mesh.face_triangle.end(), 2u) -
        a.mesh.face_triangle.begin();
    ASSERT_LT(fin_face, a.mesh.face_triangle.size());
    const auto& c = a.mesh.face_corners[fin_face];
    EXPECT_EQ(std::multiset<uint32_t>(c.begin(), c.end()), (std::multiset<uint32_t>{0, 1, 4}));
}

// A closed tetrahedron 0..3 and a triangle touching its corner 1 only.
SyntheticAlias tetra_touched_at_a_corner(bool triangle_first) {
    SyntheticAlias m({{{0, 0, 0}, {40, 0, 0}, {0, 40, 0}, {0, 0, 40}, {80, 0, 0}, {80, 40, 0}}});
    if (triangle_first) m.add_outward(1, 4, 5);
    m.add_outward(0, 2, 1);
    m.add_outward(0, 1, 3);
    m.add_outward(0, 3, 2);
    m.add_outward(1, 2, 3);
    if (!triangle_first) m.add_outward(1, 4, 5);
    return m;
}

TEST(AdjacencyMesh, TriangleTouchingAClosedFanGetsItsOwnVertex) {
    for (bool triangle_first : {false, true}) {
        SCOPED_TRACE(triangle_first ? "triangle first" : "tetrahedron first");
        SyntheticAlias m = tetra_touched_at_a_corner(triangle_first);
        const ModelAdjacency a = m.recover();
        EXPECT_TRUE(a.problems.empty());
        EXPECT_EQ(a.stats.soup.non_manifold, 0u);
        EXPECT_EQ(a.stats.splits.new_vertices, 1u);
        EXPECT_EQ(a.stats.mesh_vertices, 7u);
        EXPECT_EQ(a.stats.mesh.edges, 9u);
        EXPECT_EQ(a.stats.mesh.manifold, 6u);
        EXPECT_EQ(a.stats.mesh.boundary, 3u);
        expect_openmesh_consistent(a.mesh.mesh);
        if (!triangle_first) {
            // The tetrahedron is closed when the triangle comes: a complex vertex.
            EXPECT_EQ(a.stats.splits.complex_vertex_faces, 1u);
            EXPECT_EQ(a.stats.splits.deferred_faces, 0u);
        } else {
            // OpenMesh cannot close the tetrahedron's fan around the triangle's: that face
            // waits for the fan split, which gives the triangle its own vertex.
            EXPECT_EQ(a.stats.splits.deferred_faces, 1u);
            EXPECT_EQ(a.stats.splits.fan_splits, 1u);
            EXPECT_EQ(a.stats.splits.island_faces, 0u);
        }
    }
}

TEST(AdjacencyMesh, MoebiusStripIsCutOnce) {
    // N quads around a circle with a half twist: vertex 2i + side, and the last quad joins
    // the first with its sides swapped. Non-orientable: one edge must be cut.
    constexpr uint32_t N = 8;
    std::vector<Packed> v;
    for (uint32_t i = 0; i < N; ++i) {
        const double theta = 2 * std::numbers::pi * i / N;
        for (int side : {-1, 1}) {
            const double radial = 80 + side * 24 * std::cos(theta / 2);
            v.push_back({uint8_t(std::lround(128 + radial * std::cos(theta))),
                         uint8_t(std::lround(128 + radial * std::sin(theta))),
                         uint8_t(std::lround(128 + side * 24 * std::sin(theta / 2)))});
        }
    }
    SyntheticAlias strip({v});
    for (uint32_t i = 0; i < N; ++i) {
        const bool last = i + 1 == N;
        const uint32_t a = 2 * i, b = 2 * i + 1;
        const uint32_t c = last ? 0 : 2 * (i + 1) + 1, d = last ? 1 : 2 * (i + 1);
        strip.add_outward_quad(a, d, c, b);
    }
    const ModelAdjacency a = strip.recover();
    EXPECT_EQ(a.stats.soup.edges, 4 * N);
    EXPECT_EQ(a.stats.soup.boundary, 2 * N);
    EXPECT_EQ(a.stats.orientation_conflicts, 1u);
    EXPECT_TRUE(a.problems.empty()) << a.problems.front();
    EXPECT_EQ(a.stats.mesh.non_manifold, 0u);
    // The cut edge becomes two boundary edges, and both its ends get a second vertex.
    EXPECT_EQ(a.stats.mesh.edges, 4 * N + 1);
    EXPECT_EQ(a.stats.mesh.boundary, 2 * N + 2);
    EXPECT_EQ(a.stats.mesh_vertices, 2 * N + 2);
    expect_openmesh_consistent(a.mesh.mesh);
}

TEST(AdjacencyMesh, EmptyAndBrokenViewsGiveAnEmptyMesh) {
    nqr_alias_model empty{};
    empty.size = sizeof empty;
    empty.num_triangles = 5;  // with a null array: read as none
    empty.num_vertices = 3;
    const ModelAdjacency a = recover_adjacency(empty);
    EXPECT_EQ(a.stats.mesh_faces, 0u);
    EXPECT_TRUE(a.problems.empty());
    EXPECT_EQ(a.verdict.style, EdgeStyle::backface_lines);
    EXPECT_EQ(a.verdict.reason, "no usable triangles");
}

TEST(AdjacencyMeshChecks, ReportsATamperedFaceTable) {
    SyntheticAlias cube = test::cube_model();
    ModelAdjacency a = cube.recover();
    ASSERT_TRUE(check_mesh(a.mesh).empty());
    std::swap(a.mesh.face_vertices[0][1], a.mesh.face_vertices[0][2]);
    const auto problems = check_mesh(a.mesh);
    ASSERT_FALSE(problems.empty());
    EXPECT_EQ(problems.front(), "face 0 does not match its face table row");
}

}  // namespace
}  // namespace nq::npr::adjacency

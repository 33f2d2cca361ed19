// Smooth normals with creases: a cube keeps its 90-degree edges, a fine sphere gets the
// analytic normals, welded seam copies share a normal, degenerate triangles add nothing and
// never make a NaN, creases are voted over poses; and every pose of LibreQuake's player.mdl
// gets finite unit normals in the classic drawn-vertex layout.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include <glm/geometric.hpp>

#include "classic/alias_mesh.h"
#include "common/file_io.h"
#include "formats/mdl.h"
#include "illustrative/smooth_normals.h"
#include "render/alias_model.h"
#include "support/test_data.h"

namespace nq::npr::illustrative {
namespace {

constexpr float kPi = 3.14159265358979f;

float degrees_between(const glm::vec3& a, const glm::vec3& b) {
    return std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0f, 1.0f)) *
           180.0f / kPi;
}

// A test mesh: positions plus triangles; every position is its own drawn vertex; `weld` maps
// positions to classes (identity unless a test welds copies).
struct TestMesh {
    std::vector<glm::vec3> positions;
    std::vector<uint32_t> triangles;
    std::vector<uint32_t> weld;

    SmoothingMesh smoothing() const {
        SmoothingMesh m;
        m.indices = triangles;
        for (uint32_t p = 0; p < positions.size(); ++p) m.vertex_position.push_back(p);
        m.position_weld = weld;
        if (m.position_weld.empty()) m.position_weld = m.vertex_position;
        return m;
    }
    // Adds a triangle wound clockwise seen from outside, outside being away from `inside`.
    void add(uint32_t a, uint32_t b, uint32_t c, const glm::vec3& inside) {
        const glm::vec3 n = glm::cross(positions[c] - positions[a], positions[b] - positions[a]);
        const glm::vec3 centre = (positions[a] + positions[b] + positions[c]) / 3.0f;
        if (glm::dot(n, centre - inside) < 0.0f) std::swap(b, c);
        triangles.insert(triangles.end(), {a, b, c});
    }
};

std::vector<glm::vec3> normals_of(const TestMesh& t, const SmoothingLayout& layout) {
    std::vector<glm::vec3> out;
    compute_smooth_normals(t.smoothing(), layout, t.positions, out);
    return out;
}

TestMesh cube() {
    TestMesh t;
    for (int i = 0; i < 8; ++i) {
        t.positions.emplace_back(i & 1 ? 1.0f : -1.0f, i & 2 ? 1.0f : -1.0f, i & 4 ? 1.0f : -1.0f);
    }
    // Each face: the four corners with one coordinate fixed, split along a diagonal.
    for (int axis = 0; axis < 3; ++axis) {
        for (int side = 0; side < 2; ++side) {
            std::vector<uint32_t> quad;
            for (uint32_t i = 0; i < 8; ++i) {
                if (((i >> axis) & 1) == uint32_t(side)) quad.push_back(i);
            }
            // quad holds the corners in binary order: 0-1-3-2 goes around the face.
            t.add(quad[0], quad[1], quad[3], glm::vec3(0.0f));
            t.add(quad[0], quad[3], quad[2], glm::vec3(0.0f));
        }
    }
    return t;
}

TEST(IllustrativeSmoothNormals, CubeKeepsItsCreases) {
    const TestMesh t = cube();
    const SmoothingLayout layout = plan_smoothing_groups(t.smoothing(), t.positions, 1);
    ASSERT_TRUE(layout.error.empty()) << layout.error;
    EXPECT_EQ(layout.num_vertices(), 24u);  // each corner once per face meeting there
    EXPECT_EQ(layout.num_groups(), 24u);
    const std::vector<glm::vec3> n = normals_of(t, layout);
    for (size_t tri = 0; tri < 12; ++tri) {
        // The face's normal: the axis along which all three corners agree.
        glm::vec3 expected(0.0f);
        for (int axis = 0; axis < 3; ++axis) {
            const float c = t.positions[t.triangles[tri * 3]][axis];
            bool same = true;
            for (int k = 1; k < 3; ++k) same &= t.positions[t.triangles[tri * 3 + k]][axis] == c;
            if (same) expected[axis] = c;
        }
        for (int k = 0; k < 3; ++k) {
            const glm::vec3 got = n[layout.indices[tri * 3 + k]];
            EXPECT_LT(degrees_between(got, expected), 0.1f) << tri << " " << k;
            EXPECT_NEAR(glm::length(got), 1.0f, 1e-5f);
        }
    }
    // The first vertices are the drawn ones, in order; copies say whom they copy.
    for (uint32_t v = 0; v < 8; ++v) EXPECT_EQ(layout.source_vertex[v], v);
    for (uint32_t v = 8; v < layout.num_vertices(); ++v) {
        EXPECT_LT(layout.source_vertex[v], 8u);
    }
}

TEST(IllustrativeSmoothNormals, CubeWithCreasesOffIsRound) {
    const TestMesh t = cube();
    const SmoothingLayout layout = plan_smoothing_groups(t.smoothing(), t.positions, 1, 180.0f);
    EXPECT_EQ(layout.num_vertices(), 8u);
    const std::vector<glm::vec3> n = normals_of(t, layout);
    // By symmetry every corner's angle-weighted normal is its diagonal.
    for (uint32_t v = 0; v < 8; ++v) EXPECT_LT(degrees_between(n[v], t.positions[v]), 0.1f);
}

// A latitude-longitude sphere whose last meridian duplicates the first (a UV seam), welded.
TestMesh sphere(int stacks, int slices) {
    TestMesh t;
    std::vector<std::vector<uint32_t>> ring(size_t(stacks + 1));
    for (int i = 0; i <= stacks; ++i) {
        const float theta = kPi * float(i) / float(stacks);
        for (int j = 0; j <= slices; ++j) {
            const float phi = 2.0f * kPi * float(j % slices) / float(slices);
            ring[size_t(i)].push_back(uint32_t(t.positions.size()));
            // sin(float pi) is not 0: place the poles exactly, so their copies weld.
            const float r = (i == 0 || i == stacks) ? 0.0f : std::sin(theta);
            const float z = i == 0 ? 1.0f : (i == stacks ? -1.0f : std::cos(theta));
            t.positions.emplace_back(r * std::cos(phi), r * std::sin(phi), z);
        }
    }
    // Weld: positions at exactly the same place (seam copies, the pole rings) share a class.
    std::map<std::tuple<float, float, float>, uint32_t> first;
    for (uint32_t p = 0; p < t.positions.size(); ++p) {
        glm::vec3 q = t.positions[p];
        if (q.x == 0.0f && q.y == 0.0f) q = glm::vec3(0.0f, 0.0f, q.z);  // -0 at the poles
        const auto key = std::make_tuple(q.x, q.y, q.z);
        t.weld.push_back(first.try_emplace(key, p).first->second);
    }
    for (int i = 0; i < stacks; ++i) {
        for (int j = 0; j < slices; ++j) {
            const uint32_t a = ring[i][j], b = ring[i][j + 1], c = ring[i + 1][j],
                           d = ring[i + 1][j + 1];
            if (i > 0) t.add(a, b, d, glm::vec3(0.0f));
            if (i + 1 < stacks) t.add(a, d, c, glm::vec3(0.0f));
        }
    }
    return t;
}

TEST(IllustrativeSmoothNormals, FineSphereGetsAnalyticNormals) {
    const TestMesh t = sphere(24, 48);
    const SmoothingLayout layout = plan_smoothing_groups(t.smoothing(), t.positions, 1);
    ASSERT_TRUE(layout.error.empty());
    EXPECT_EQ(layout.num_vertices(), t.positions.size());  // no creases, nothing appended
    const std::vector<glm::vec3> n = normals_of(t, layout);
    for (size_t c = 0; c < t.triangles.size(); ++c) {
        const uint32_t v = layout.indices[c];
        const glm::vec3 p = t.positions[layout.source_vertex[v]];
        ASSERT_LT(degrees_between(n[v], p), 3.0f) << c;
    }
}

TEST(IllustrativeSmoothNormals, SeamCopiesShareTheirNormal) {
    const TestMesh t = sphere(12, 16);
    const SmoothingLayout layout = plan_smoothing_groups(t.smoothing(), t.positions, 1);
    const std::vector<glm::vec3> n = normals_of(t, layout);
    // The first and last meridian are different drawn vertices at the same place.
    for (int i = 1; i < 12; ++i) {
        const uint32_t first = uint32_t(i * 17), last = uint32_t(i * 17 + 16);
        ASSERT_EQ(t.positions[first], t.positions[last]);
        EXPECT_EQ(n[first], n[last]) << i;
        EXPECT_LT(degrees_between(n[first], t.positions[first]), 3.0f);
    }
    // Without the weld the seam would be a boundary and its normals would differ.
    TestMesh unwelded = t;
    unwelded.weld.clear();
    const SmoothingLayout apart = plan_smoothing_groups(unwelded.smoothing(), t.positions, 1);
    const std::vector<glm::vec3> m = normals_of(unwelded, apart);
    EXPECT_GT(degrees_between(m[17 * 6], m[17 * 6 + 16]), 5.0f);
}

TEST(IllustrativeSmoothNormals, DegenerateTrianglesAddNothing) {
    TestMesh t = cube();
    const std::vector<glm::vec3> before =
        normals_of(t, plan_smoothing_groups(t.smoothing(), t.positions, 1));
    // A sliver with a repeated corner, one with three collinear corners, and a lone vertex
    // used only by a degenerate triangle.
    t.positions.emplace_back(1.0f, 0.0f, 1.0f);  // 8: on the +X +Z edge midpoint
    t.positions.emplace_back(5.0f, 5.0f, 5.0f);  // 9: alone
    t.triangles.insert(t.triangles.end(), {0, 0, 7, 5, 8, 7, 9, 9, 9});
    const SmoothingLayout layout = plan_smoothing_groups(t.smoothing(), t.positions, 1);
    ASSERT_TRUE(layout.error.empty());
    const std::vector<glm::vec3> after = normals_of(t, layout);
    for (const glm::vec3& v : after) {
        EXPECT_TRUE(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z));
        EXPECT_NEAR(glm::length(v), 1.0f, 1e-5f);
    }
    // The cube's own 36 corners keep their normals.
    const SmoothingLayout plain = plan_smoothing_groups(cube().smoothing(), cube().positions, 1);
    for (size_t c = 0; c < 36; ++c) {
        EXPECT_LT(degrees_between(after[layout.indices[c]], before[plain.indices[c]]), 0.1f);
    }
}

// Two triangles sharing the edge (0,0,0)-(0,1,0): flat in some poses, folded 90 degrees in
// others.
TestMesh hinge(const std::vector<bool>& folded, std::vector<glm::vec3>& poses) {
    TestMesh t;
    t.positions = {{0, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {1, 0, 0}};
    t.triangles = {0, 2, 1, 0, 1, 3};  // both facing +Z when flat (clockwise seen from +Z)
    for (bool f : folded) {
        poses.insert(poses.end(), {{0, 0, 0}, {0, 1, 0}, {-1, 0, 0}});
        poses.push_back(f ? glm::vec3(0, 0, -1) : glm::vec3(1, 0, 0));
    }
    return t;
}

TEST(IllustrativeSmoothNormals, CreasesAreVotedOverPoses) {
    std::vector<glm::vec3> poses;
    TestMesh t = hinge({false, true, true}, poses);
    SmoothingLayout layout = plan_smoothing_groups(t.smoothing(), poses, 3);
    EXPECT_EQ(layout.num_groups(), 6u);  // sharp in 2 of 3 poses: every corner on its own
    poses.clear();
    t = hinge({false, false, true}, poses);
    layout = plan_smoothing_groups(t.smoothing(), poses, 3);
    EXPECT_EQ(layout.num_groups(), 4u);  // sharp in 1 of 3: the hinge's two ends are smooth
    EXPECT_EQ(layout.num_vertices(), 4u);
    const std::vector<glm::vec3> n = normals_of(t, layout);  // the flat pose 0
    EXPECT_LT(degrees_between(n[0], glm::vec3(0, 0, 1)), 0.1f);
}

TEST(IllustrativeSmoothNormals, InconsistentMeshIsAnError) {
    TestMesh t = cube();
    t.triangles.push_back(99);
    EXPECT_FALSE(plan_smoothing_groups(t.smoothing(), t.positions, 1).error.empty());
    t.triangles.insert(t.triangles.end(), {1, 2});
    const SmoothingLayout layout = plan_smoothing_groups(t.smoothing(), t.positions, 1);
    EXPECT_FALSE(layout.error.empty());
    std::vector<glm::vec3> n;
    compute_smooth_normals(t.smoothing(), layout, t.positions, n);  // no crash, nothing
    EXPECT_TRUE(n.empty());
}

TEST(IllustrativeSmoothNormals, PlayerModelEveryPoseFiniteAndUnit) {
    const std::string path = test::lq1_dir() + "/progs/player.mdl";
    auto bytes = read_file(path);
    ASSERT_TRUE(bytes) << bytes.error().to_string();
    auto mdl = parse_mdl(*bytes, path);
    ASSERT_TRUE(mdl) << mdl.error().to_string();
    const auto data = AliasModelData::build(std::move(*mdl));
    const nqr_alias_model& model = data->abi();
    const classic::AliasMesh mesh = classic::build_alias_mesh(model);
    const AliasSmoothNormals s = compute_alias_smooth_normals(model, mesh);
    ASSERT_TRUE(s.layout.error.empty()) << s.layout.error;
    EXPECT_EQ(s.num_poses, model.num_poses);
    EXPECT_EQ(s.layout.num_drawn_vertices, mesh.vertices.size());
    EXPECT_GE(s.layout.num_vertices(), mesh.vertices.size());
    ASSERT_EQ(s.layout.indices.size(), mesh.indices.size());
    ASSERT_EQ(s.normals.size(), size_t(s.num_poses) * s.layout.num_vertices());
    for (const glm::vec3& v : s.normals) {
        ASSERT_TRUE(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z));
        ASSERT_NEAR(glm::length(v), 1.0f, 1e-4f);
    }
    // Every corner still draws the same MDL vertex as the classic layout.
    for (size_t c = 0; c < mesh.indices.size(); ++c) {
        const uint32_t source = s.layout.source_vertex[s.layout.indices[c]];
        EXPECT_EQ(mesh.vertices[source].pose_vertex, mesh.vertices[mesh.indices[c]].pose_vertex);
    }
    // Normals point outward overall: on average they agree with the classic smooth normals.
    std::vector<float> classic_normals;
    classic::compute_pose_normals(model, 0, classic_normals);
    double agreement = 0.0;
    for (uint32_t v = 0; v < mesh.vertices.size(); ++v) {
        const uint32_t p = mesh.vertices[v].pose_vertex;
        const glm::vec3 c(classic_normals[p * 3], classic_normals[p * 3 + 1],
                          classic_normals[p * 3 + 2]);
        agreement += glm::dot(c, s.pose(0)[v]);
    }
    EXPECT_GT(agreement / double(mesh.vertices.size()), 0.8);
}

}  // namespace
}  // namespace nq::npr::illustrative

// Adjacency recovery on every model in LibreQuake's progs/: OpenMesh's consistency checks pass,
// no non-manifold edge remains, welds never join vertices that part in some frame, and the
// counts of fins and degenerate triangles agree with independent brute-force counts.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <set>
#include <string>

#include "adjacency/alias_source.h"
#include "adjacency/model_adjacency.h"
#include "adjacency/paper_baseline.h"
#include "common/file_io.h"
#include "formats/mdl.h"
#include "render/alias_model.h"
#include "support/test_data.h"

namespace nq::npr::adjacency {
namespace {

std::shared_ptr<const AliasModelData> load(const std::string& path) {
    auto bytes = read_file(path);
    if (!bytes) throw std::runtime_error(bytes.error().to_string());
    auto mdl = parse_mdl(*bytes, path);
    if (!mdl) throw std::runtime_error(mdl.error().to_string());
    return AliasModelData::build(std::move(*mdl));
}

std::string progs(const std::string& name) {
    return test::lq1_dir() + "/progs/" + name;
}

// Independent of the library: a vertex's packed position in every pose, as one string.
std::string trajectory(const nqr_alias_model& m, uint32_t v) {
    std::string key;
    for (uint32_t p = 0; p < m.num_poses; ++p) {
        const nqr_alias_vertex& x = m.poses[size_t(p) * m.num_vertices + v];
        key.append(reinterpret_cast<const char*>(x.v), 3);
    }
    return key;
}

bool collinear_in_every_pose(const nqr_alias_model& m, const int32_t* t) {
    for (uint32_t p = 0; p < m.num_poses; ++p) {
        glm::vec3 q[3];
        for (int k = 0; k < 3; ++k) {
            const nqr_alias_vertex& x = m.poses[size_t(p) * m.num_vertices + t[k]];
            for (int i = 0; i < 3; ++i) q[k][i] = m.scale[i] * x.v[i] + m.origin[i];
        }
        if (glm::cross(q[1] - q[0], q[2] - q[0]) != glm::vec3(0.0f)) return false;
    }
    return true;
}

TEST(AdjacencyRealData, EveryProgsModelGivesACleanManifoldMesh) {
    EdgeCensus ours, paper;
    size_t models = 0, true_edges = 0;
    for (const std::string& path : test::lq1_files("progs", ".mdl")) {
        SCOPED_TRACE(path);
        const auto data = load(path);
        const nqr_alias_model& m = data->abi();
        const ModelAdjacency a = recover_adjacency(m);
        EXPECT_TRUE(a.problems.empty()) << a.problems.front();
        EXPECT_EQ(a.stats.mesh.non_manifold, 0u);
        const TriMesh& mesh = a.mesh.mesh;
        for (const auto v : mesh.vertices()) {
            ASSERT_TRUE(mesh.is_manifold(v)) << v.idx();
            ASSERT_FALSE(mesh.is_isolated(v)) << v.idx();
        }
        for (const auto h : mesh.halfedges()) {
            ASSERT_TRUE(mesh.opposite_halfedge_handle(h).is_valid());
            ASSERT_TRUE(mesh.next_halfedge_handle(h).is_valid());
            ASSERT_EQ(mesh.prev_halfedge_handle(mesh.next_halfedge_handle(h)), h);
        }
        EXPECT_EQ(a.stats.mesh_faces + a.stats.removed.degenerate() + a.stats.removed.duplicates(),
                  m.num_triangles);
        // A face corner's MDL vertex is where its mesh vertex is, in every pose.
        for (size_t f = 0; f < a.mesh.face_corners.size(); ++f) {
            for (int k = 0; k < 3; ++k) {
                const uint32_t corner = a.mesh.face_corners[f][k];
                const uint32_t at = a.mesh.vertex_mdl[a.mesh.face_vertices[f][k]];
                ASSERT_EQ(trajectory(m, corner), trajectory(m, at)) << "face " << f;
            }
        }
        ++models;
        true_edges += a.verdict.style == EdgeStyle::true_edges;
        ours.edges += a.stats.mesh.edges;
        ours.consistent += a.stats.mesh.consistent;
        const BaselineReport b = run_paper_baseline(AliasSource(m));
        paper.edges += b.first_pose.edges;
        paper.consistent += b.first_pose.consistent;
        paper.non_manifold += b.first_pose.non_manifold;
    }
    std::printf(
        "%zu models, %zu with true edges; manifold and consistent: %.1f%% recovered, "
        "%.1f%% paper (frame 0, %u non-manifold edges)\n",
        models, true_edges, 100 * ours.consistent_share(), 100 * paper.consistent_share(),
        paper.non_manifold);
    EXPECT_GT(paper.non_manifold, 0u);  // what the recovery removes
}

TEST(AdjacencyRealData, VerticesThatTouchOnlyInFrame0StayApart) {
    for (const char* name : {"v_rock2.mdl", "player.mdl"}) {
        SCOPED_TRACE(name);
        const auto data = load(progs(name));
        const nqr_alias_model& m = data->abi();
        const ModelAdjacency a = recover_adjacency(m);
        // Pairs equal in pose 0 but different in a later pose, found by brute force.
        size_t parting = 0;
        for (uint32_t i = 0; i < m.num_vertices; ++i) {
            for (uint32_t j = i + 1; j < m.num_vertices; ++j) {
                if (std::memcmp(m.poses[i].v, m.poses[j].v, 3) != 0) continue;
                if (trajectory(m, i) == trajectory(m, j)) continue;
                ++parting;
                // Never one mesh vertex (or none is used).
                const uint32_t vi = a.mdl_to_mesh_vertex[i], vj = a.mdl_to_mesh_vertex[j];
                if (vi != kNone) {
                    EXPECT_NE(vi, vj);
                }
            }
        }
        EXPECT_GT(parting, 0u);
        EXPECT_GT(a.stats.kept_apart, 0u);
    }
}

TEST(AdjacencyRealData, FinsAndDegeneratesMatchBruteForceCounts) {
    size_t fins_total = 0;
    for (const std::string& path : test::lq1_files("progs", ".mdl")) {
        SCOPED_TRACE(path);
        const auto data = load(path);
        const nqr_alias_model& m = data->abi();
        const ModelAdjacency a = recover_adjacency(m);
        // Degenerate: a repeated index, or no area in any pose (collinear or coincident).
        uint32_t degenerate = 0;
        for (uint32_t t = 0; t < m.num_triangles; ++t) {
            const int32_t* v = m.triangles + 4 * t + 1;
            degenerate +=
                v[0] == v[1] || v[1] == v[2] || v[0] == v[2] || collinear_in_every_pose(m, v);
        }
        EXPECT_EQ(a.stats.removed.degenerate(), degenerate);
        // Edges between positions-over-all-poses used by three or more distinct triangles.
        std::map<std::pair<std::string, std::string>, std::set<std::multiset<std::string>>> uses;
        for (uint32_t t = 0; t < m.num_triangles; ++t) {
            const int32_t* v = m.triangles + 4 * t + 1;
            if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2] || collinear_in_every_pose(m, v))
                continue;
            const std::multiset<std::string> triangle{trajectory(m, v[0]), trajectory(m, v[1]),
                                                      trajectory(m, v[2])};
            for (int k = 0; k < 3; ++k) {
                auto x = trajectory(m, v[k]), y = trajectory(m, v[(k + 1) % 3]);
                if (y < x) std::swap(x, y);
                uses[{x, y}].insert(triangle);  // duplicates and twins count once
            }
        }
        uint32_t fins = 0;
        for (const auto& [edge, triangles] : uses) fins += triangles.size() >= 3;
        EXPECT_EQ(a.stats.soup.non_manifold, fins);
        fins_total += fins;
    }
    EXPECT_GT(fins_total, 0u);  // "a few have edges shared by three triangles"
}

TEST(AdjacencyRealData, ClosedMonsterGetsTrueEdges) {
    const auto data = load(progs("demon.mdl"));
    const ModelAdjacency a = recover_adjacency(data->abi());
    EXPECT_EQ(a.stats.mesh.boundary, 0u);
    EXPECT_EQ(a.verdict.style, EdgeStyle::true_edges);
    // A renderer's recovery keeps no per-pose geometry; asked for, every pose's face planes.
    EXPECT_TRUE(a.geometry.planes.empty());
    const ModelAdjacency with_geometry = recover_adjacency(data->abi(), {kMinManifoldShare, true});
    EXPECT_EQ(with_geometry.geometry.planes.size(),
              size_t(data->abi().num_poses) * with_geometry.stats.mesh_faces);
}

}  // namespace
}  // namespace nq::npr::adjacency

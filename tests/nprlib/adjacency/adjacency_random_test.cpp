// Random soups on a coarse grid (so that vertices coincide, edges are shared by many triangles,
// twins and fins abound, and some parts touch in one pose only): whatever the input, the mesh
// passes every consistency check, has no non-manifold edge, accounts for every triangle, and
// each face corner's MDL vertex lies where its mesh vertex is in every pose.
#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "adjacency/model_adjacency.h"
#include "adjacency_test_models.h"
#include "common/file_io.h"
#include "formats/mdl.h"
#include "render/alias_model.h"
#include "support/test_data.h"

namespace nq::npr::adjacency {
namespace {

using test::Packed;
using test::SyntheticAlias;

SyntheticAlias random_soup(std::mt19937& rng) {
    auto pick = [&](uint32_t n) { return std::uniform_int_distribution<uint32_t>(0, n - 1)(rng); };
    const uint32_t vertices = 4 + pick(14), poses = 1 + pick(3), grid = 2 + pick(3);
    std::vector<std::vector<Packed>> frames(poses);
    for (uint32_t v = 0; v < vertices; ++v) {
        const bool moves = pick(3) == 0;  // most vertices keep their place: coincidences last
        Packed p{uint8_t(10 * pick(grid)), uint8_t(10 * pick(grid)), uint8_t(10 * pick(grid))};
        for (uint32_t f = 0; f < poses; ++f) {
            if (moves && f > 0) p[pick(3)] = uint8_t(10 * pick(grid));
            frames[f].push_back(p);
        }
    }
    SyntheticAlias model(frames);
    const uint32_t triangles = 1 + pick(40);
    for (uint32_t t = 0; t < triangles; ++t)
        model.add_stored(pick(vertices), pick(vertices), pick(vertices));
    return model;
}

TEST(AdjacencyRandom, EverySoupGivesACheckedManifoldMesh) {
    std::mt19937 rng(20240611);
    for (int round = 0; round < 400; ++round) {
        SCOPED_TRACE("round " + std::to_string(round));
        SyntheticAlias model = random_soup(rng);
        const nqr_alias_model& m = model.view();
        const ModelAdjacency a = recover_adjacency(m);
        ASSERT_TRUE(a.problems.empty()) << a.problems.front();
        ASSERT_EQ(a.stats.mesh.non_manifold, 0u);
        ASSERT_EQ(a.stats.mesh.consistent, a.stats.mesh.manifold);
        ASSERT_EQ(a.stats.mesh_faces + a.stats.removed.degenerate() + a.stats.removed.duplicates(),
                  m.num_triangles);
        for (size_t f = 0; f < a.mesh.face_corners.size(); ++f) {
            for (int k = 0; k < 3; ++k) {
                const uint32_t corner = a.mesh.face_corners[f][k];
                const uint32_t at = a.mesh.vertex_mdl[a.mesh.face_vertices[f][k]];
                for (uint32_t p = 0; p < m.num_poses; ++p) {
                    const auto* pose = m.poses + size_t(p) * m.num_vertices;
                    ASSERT_EQ(std::memcmp(pose[corner].v, pose[at].v, 3), 0);
                }
            }
        }
        // The records a renderer tests per frame index real vertices and mark the borders.
        ASSERT_EQ(a.edges.records.size(), a.edges.edges.size());
        for (size_t e = 0; e < a.edges.records.size(); ++e) {
            const EdgeRecord& r = a.edges.records[e];
            for (uint32_t v : {r.third, r.v0, r.v1, r.far}) ASSERT_LT(v, m.num_vertices);
            ASSERT_EQ(r.border(), a.edges.edges[e].boundary());
        }
        ASSERT_LE(a.file.triangles.size(), m.num_triangles);
        ASSERT_EQ(a.file.twins.size(), a.file.triangles.size());
        ASSERT_EQ(a.file.seam_representatives.size(), m.num_vertices);
        for (uint32_t v = 0; v < m.num_vertices; ++v) {
            ASSERT_LE(a.file.seam_representatives[v], v);
        }
    }
}

// Real models with random damage to their ABI views: triangle indices rewired (some out of
// range), vertices moved in some poses. Recovery must still give a checked manifold mesh.
TEST(AdjacencyRandom, DamagedRealModelsStillGiveCheckedMeshes) {
    std::mt19937 rng(99);
    auto pick = [&](uint32_t n) { return std::uniform_int_distribution<uint32_t>(0, n - 1)(rng); };
    for (const char* name : {"gib1.mdl", "h_dog.mdl", "s_light.mdl", "bolt3.mdl"}) {
        auto bytes = read_file(test::lq1_dir() + "/progs/" + name);
        ASSERT_TRUE(bytes.ok());
        auto mdl = parse_mdl(*bytes, name);
        ASSERT_TRUE(mdl.ok());
        const auto data = AliasModelData::build(std::move(*mdl));
        const nqr_alias_model& original = data->abi();
        for (int round = 0; round < 25; ++round) {
            SCOPED_TRACE(std::string(name) + " round " + std::to_string(round));
            std::vector<int32_t> triangles(original.triangles,
                                           original.triangles + 4 * original.num_triangles);
            std::vector<nqr_alias_vertex> poses(
                original.poses,
                original.poses + size_t(original.num_poses) * original.num_vertices);
            for (int k = 0; k < 1 + round; ++k) {
                const uint32_t slot = 4 * pick(original.num_triangles) + 1 + pick(3);
                triangles[slot] = int32_t(pick(original.num_vertices + 2)) - 1;  // -1 .. n
                poses[pick(uint32_t(poses.size()))].v[pick(3)] = uint8_t(pick(256));
            }
            nqr_alias_model damaged = original;
            damaged.triangles = triangles.data();
            damaged.poses = poses.data();
            const ModelAdjacency a = recover_adjacency(damaged);
            ASSERT_TRUE(a.problems.empty()) << a.problems.front();
            ASSERT_EQ(a.stats.mesh.non_manifold, 0u);
            ASSERT_EQ(a.stats.mesh_faces + a.stats.removed.degenerate() +
                          a.stats.removed.duplicates() + a.stats.removed.bad_index,
                      damaged.num_triangles);
        }
    }
}

}  // namespace
}  // namespace nq::npr::adjacency

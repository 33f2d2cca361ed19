// World culling on the LibreQuake maps: from start.bsp's player start the visible list is
// non-empty, smaller than the world, holds the floor under the player, is grouped by texture in
// front-to-back order, equals the brute-force PVS set without a frustum and lies within it with
// one; maps without vis data and eyes outside the map see everything; and after warm-up cull()
// allocates nothing (counted by replacing the global operator new in this test binary).
#include <gtest/gtest.h>

#include <set>

#include "formats/entities.h"
#include "render/view_transform.h"
#include "render/world_culler.h"
#include "support/render_test_support.h"
#include "support/allocation_counter.h"
#include "support/synth_bsp.h"

namespace nq {
namespace {

struct MapFixture {
    std::shared_ptr<const BrushModelData> data;
    const Bsp& bsp() const { return data->bsp(); }
    glm::vec3 player_start() const {
        auto entities = parse_entities(bsp().entities, "entities");
        if (!entities) throw std::runtime_error(entities.error().to_string());
        for (const Entity* e : find_entities(*entities, "info_player_start")) {
            if (auto o = find_vec3(*e, "origin")) return {(*o)[0], (*o)[1], (*o)[2]};
        }
        throw std::runtime_error("no info_player_start");
    }
    std::set<uint32_t> world_faces() const {
        std::set<uint32_t> faces;
        const BspModel& world = bsp().models[0];
        for (uint32_t f = world.first_face; f < world.first_face + world.num_faces; ++f) {
            faces.insert(f);
        }
        return faces;
    }
};

MapFixture load(const std::string& path) {
    return {render_test::load_map(path)};
}

Frustum frustum_for(const glm::vec3& eye, const glm::vec3& angles) {
    CameraSetup setup;
    setup.origin = eye;
    setup.angles = angles;
    setup.fov_x = 90;
    nqr_camera camera;
    fill_camera(setup, camera);
    return Frustum::from_view_projection(load_matrix(camera.view_projection));
}

std::vector<uint32_t> cull(WorldCuller& culler, const glm::vec3& eye, const Frustum& frustum) {
    std::vector<uint32_t> out(culler.max_visible_surfaces());
    out.resize(culler.cull(eye, frustum, out));
    return out;
}

// The world leafs the parser's own PVS decoder marks visible from `eye` (all of them when the
// eye's leaf has no row or is leaf 0).
std::set<uint32_t> brute_force_pvs_leafs(const Bsp& bsp, const glm::vec3& eye) {
    const uint32_t leaf = leaf_at(bsp, {eye.x, eye.y, eye.z});
    const bool all = leaf == 0 || bsp.leafs[leaf].vis_offset < 0;
    const std::vector<uint8_t> row = decompress_vis(bsp, leaf);
    std::set<uint32_t> leafs;
    for (uint32_t l = 1; l <= bsp.models[0].visleafs; ++l) {
        if (all || pvs_contains(row, l)) leafs.insert(l);
    }
    return leafs;
}

// Every world surface listed by one of those leafs.
std::set<uint32_t> brute_force_pvs_surfaces(const Bsp& bsp, const glm::vec3& eye) {
    std::set<uint32_t> faces;
    const BspModel& world = bsp.models[0];
    for (uint32_t l : brute_force_pvs_leafs(bsp, eye)) {
        const BspLeaf& bl = bsp.leafs[l];
        for (uint32_t i = 0; i < bl.num_marksurfaces; ++i) {
            const uint32_t f = bsp.marksurfaces[bl.first_marksurface + i];
            if (f >= world.first_face && f < world.first_face + world.num_faces) faces.insert(f);
        }
    }
    return faces;
}

// The face under the player: trace_down's plane, and a polygon (from the ABI positions) that
// holds the hit point.
uint32_t floor_face(const MapFixture& map, const glm::vec3& from) {
    const BspTrace t = trace_down(map.bsp(), {from.x, from.y, from.z}, 2048);
    EXPECT_TRUE(t.hit());
    const glm::vec3 hit(t.end[0], t.end[1], t.end[2]);
    const nqr_brush_model& brush = map.data->abi();
    for (uint32_t i = 0; i < brush.num_surfaces; ++i) {
        const nqr_surface& s = *nqr_at(nqr_surface, brush.surfaces, i);
        const glm::vec3 n(s.normal[0], s.normal[1], s.normal[2]);
        if (glm::dot(n, glm::vec3(t.plane_normal[0], t.plane_normal[1], t.plane_normal[2])) <
                0.999f ||
            std::fabs(glm::dot(n, hit) - s.dist) > 0.1f) {
            continue;
        }
        bool inside = true;
        for (uint32_t k = 0; k < s.num_vertices && inside; ++k) {
            const float* a = brush.positions + 3 * (s.first_vertex + k);
            const float* b = brush.positions + 3 * (s.first_vertex + (k + 1) % s.num_vertices);
            const glm::vec3 pa(a[0], a[1], a[2]), pb(b[0], b[1], b[2]);
            inside = glm::dot(glm::cross(pb - pa, hit - pa), n) >= -1e-3f;  // left of each edge
        }
        if (inside) return i;
    }
    ADD_FAILURE() << "no face under the point";
    return 0;
}

TEST(RenderWorldCuller, StartMapFromThePlayerStart) {
    const MapFixture map = load("maps/start.bsp");
    const glm::vec3 eye = map.player_start() + glm::vec3(0, 0, 22);  // Quake's view height
    WorldCuller culler(map.bsp());
    EXPECT_EQ(culler.max_visible_surfaces(), map.world_faces().size());

    const Frustum looking_down = frustum_for(eye, {60, 0, 0});
    const std::vector<uint32_t> visible = cull(culler, eye, looking_down);
    ASSERT_FALSE(visible.empty());
    EXPECT_LT(visible.size(), map.world_faces().size());
    EXPECT_NE(culler.eye_leaf(), 0u);
    EXPECT_GT(culler.pvs_leaf_count(), 0u);
    EXPECT_LT(culler.pvs_leaf_count(), map.bsp().models[0].visleafs);

    const std::set<uint32_t> unique(visible.begin(), visible.end());
    EXPECT_EQ(unique.size(), visible.size()) << "no surface twice";
    EXPECT_TRUE(unique.count(floor_face(map, map.player_start())));
    const std::set<uint32_t> pvs = brute_force_pvs_surfaces(map.bsp(), eye);
    for (uint32_t f : visible) EXPECT_TRUE(pvs.count(f)) << "surface " << f << " not in the PVS";

    // Each texture's surfaces together, in one run.
    const nqr_brush_model& brush = map.data->abi();
    auto texture_of = [&](uint32_t f) { return nqr_at(nqr_surface, brush.surfaces, f)->texture; };
    std::set<uint32_t> finished;
    for (size_t i = 1; i < visible.size(); ++i) {
        if (texture_of(visible[i]) == texture_of(visible[i - 1])) continue;
        EXPECT_TRUE(finished.insert(texture_of(visible[i - 1])).second);
        EXPECT_FALSE(finished.count(texture_of(visible[i]))) << "texture split at " << i;
    }
}

// The BSP tree's front-to-back order from `eye`: near child first at every node, each world
// surface of a PVS leaf at its first sight.
void walk_front_to_back(const Bsp& bsp, int32_t node, const glm::vec3& eye,
                        const std::set<uint32_t>& pvs_leafs, std::vector<uint32_t>& order,
                        std::set<uint32_t>& seen) {
    if (node < 0) {
        const auto l = static_cast<uint32_t>(-(node + 1));
        if (!pvs_leafs.count(l)) return;
        const BspLeaf& leaf = bsp.leafs[l];
        const BspModel& world = bsp.models[0];
        for (uint32_t i = 0; i < leaf.num_marksurfaces; ++i) {
            const uint32_t f = bsp.marksurfaces[leaf.first_marksurface + i];
            const bool in_world = f >= world.first_face && f < world.first_face + world.num_faces;
            if (in_world && seen.insert(f).second) order.push_back(f);
        }
        return;
    }
    const BspNode& n = bsp.nodes[static_cast<size_t>(node)];
    const BspPlane& p = bsp.planes[n.plane];
    const float d = p.normal[0] * eye.x + p.normal[1] * eye.y + p.normal[2] * eye.z - p.dist;
    const int near = d >= 0 ? 0 : 1;
    walk_front_to_back(bsp, n.children[near], eye, pvs_leafs, order, seen);
    walk_front_to_back(bsp, n.children[near ^ 1], eye, pvs_leafs, order, seen);
}

// The list is that order grouped by texture, the groups in the order of their nearest surface:
// drawn in order, the frame goes roughly front to back and depth testing skips hidden shading.
TEST(RenderWorldCuller, SurfacesComeFrontToBackGroupedByTexture) {
    const MapFixture map = load("maps/start.bsp");
    const glm::vec3 eye = map.player_start() + glm::vec3(0, 0, 22);
    WorldCuller culler(map.bsp());
    const std::vector<uint32_t> visible = cull(culler, eye, Frustum{});
    std::vector<uint32_t> walk;
    std::set<uint32_t> seen;
    walk_front_to_back(map.bsp(), map.bsp().models[0].headnodes[0], eye,
                       brute_force_pvs_leafs(map.bsp(), eye), walk, seen);
    ASSERT_EQ(walk.size(), visible.size());

    const nqr_brush_model& brush = map.data->abi();
    auto texture_of = [&](uint32_t f) { return nqr_at(nqr_surface, brush.surfaces, f)->texture; };
    std::vector<uint32_t> expected;
    std::set<uint32_t> grouped;
    for (uint32_t first : walk) {
        if (!grouped.insert(texture_of(first)).second) continue;
        for (uint32_t f : walk) {
            if (texture_of(f) == texture_of(first)) expected.push_back(f);
        }
    }
    ASSERT_EQ(visible.size(), expected.size());
    for (size_t i = 0; i < visible.size(); ++i) {
        ASSERT_EQ(visible[i], expected[i])
            << "at " << i << " of " << visible.size() << ", texture " << texture_of(visible[i])
            << " vs " << texture_of(expected[i]);
    }
}

TEST(RenderWorldCuller, WithoutAFrustumTheResultIsExactlyThePvsSet) {
    const MapFixture map = load("maps/start.bsp");
    WorldCuller culler(map.bsp());
    // From every leaf's centre that is open space.
    size_t checked = 0;
    for (uint32_t l = 1; l <= map.bsp().models[0].visleafs; ++l) {
        const BspLeaf& leaf = map.bsp().leafs[l];
        const glm::vec3 center = (glm::vec3(leaf.mins[0], leaf.mins[1], leaf.mins[2]) +
                                  glm::vec3(leaf.maxs[0], leaf.maxs[1], leaf.maxs[2])) *
                                 0.5f;
        if (leaf_at(map.bsp(), {center.x, center.y, center.z}) != l) continue;
        const std::vector<uint32_t> visible = cull(culler, center, Frustum{});
        EXPECT_EQ(std::set<uint32_t>(visible.begin(), visible.end()),
                  brute_force_pvs_surfaces(map.bsp(), center))
            << "leaf " << l;
        ++checked;
    }
    EXPECT_GT(checked, 10u);
}

TEST(RenderWorldCuller, EyeOutsideTheMapSeesEverything) {
    const MapFixture map = load("maps/start.bsp");
    WorldCuller culler(map.bsp());
    const glm::vec3 outside(30000, 30000, 30000);
    const std::vector<uint32_t> visible = cull(culler, outside, Frustum{});
    EXPECT_EQ(culler.eye_leaf(), 0u);
    EXPECT_EQ(std::set<uint32_t>(visible.begin(), visible.end()),
              brute_force_pvs_surfaces(map.bsp(), outside));
    EXPECT_EQ(visible.size(), map.world_faces().size());
    // The frustum still applies: looking away from the map sees nothing.
    EXPECT_TRUE(cull(culler, outside, frustum_for(outside, {-45, 45, 0})).empty());
}

TEST(RenderWorldCuller, MapWithoutVisDataSeesEveryWorldSurface) {
    const MapFixture map = load("maps/lqdm4_a6.bsp");
    ASSERT_TRUE(map.bsp().visibility.empty());
    WorldCuller culler(map.bsp());
    const glm::vec3 eye = map.player_start() + glm::vec3(0, 0, 22);
    const std::vector<uint32_t> all = cull(culler, eye, Frustum{});
    EXPECT_EQ(std::set<uint32_t>(all.begin(), all.end()), brute_force_pvs_surfaces(map.bsp(), eye));
    EXPECT_GT(all.size(), map.world_faces().size() * 9 / 10);
    const std::vector<uint32_t> ahead = cull(culler, eye, frustum_for(eye, {0, 90, 0}));
    EXPECT_FALSE(ahead.empty());
    EXPECT_LT(ahead.size(), all.size());
}

TEST(RenderWorldCuller, BoxVisibilityFollowsThePvs) {
    const MapFixture map = load("maps/start.bsp");
    WorldCuller culler(map.bsp());
    const glm::vec3 eye = map.player_start() + glm::vec3(0, 0, 22);
    EXPECT_FALSE(culler.box_potentially_visible(eye - 16.0f, eye + 16.0f)) << "before any cull";
    cull(culler, eye, Frustum{});
    EXPECT_TRUE(culler.box_potentially_visible(eye - 16.0f, eye + 16.0f));
    EXPECT_TRUE(culler.leaf_potentially_visible(culler.eye_leaf()));
    EXPECT_FALSE(culler.box_potentially_visible(glm::vec3(30000), glm::vec3(30010)));
    // A leaf the PVS leaves out is not visible, and a box inside it neither.
    const uint32_t leafs = map.bsp().models[0].visleafs;
    for (uint32_t l = 1; l <= leafs; ++l) {
        if (culler.leaf_potentially_visible(l)) continue;
        const BspLeaf& leaf = map.bsp().leafs[l];
        const glm::vec3 center = (glm::vec3(leaf.mins[0], leaf.mins[1], leaf.mins[2]) +
                                  glm::vec3(leaf.maxs[0], leaf.maxs[1], leaf.maxs[2])) *
                                 0.5f;
        if (leaf_at(map.bsp(), {center.x, center.y, center.z}) != l) continue;
        EXPECT_FALSE(culler.box_potentially_visible(center - 0.5f, center + 0.5f)) << "leaf " << l;
    }
}

TEST(RenderWorldCuller, NoAllocationPerFrameAfterWarmUp) {
    const MapFixture map = load("maps/lqdm9_a7.bsp");
    const MapFixture start = load("maps/start.bsp");
    WorldCuller culler(map.bsp()), start_culler(start.bsp());
    std::vector<uint32_t> out(culler.max_visible_surfaces());
    std::vector<uint32_t> start_out(start_culler.max_visible_surfaces());
    const glm::vec3 eye = map.player_start() + glm::vec3(0, 0, 22);
    const glm::vec3 start_eye = start.player_start() + glm::vec3(0, 0, 22);
    std::vector<Frustum> frustums;
    for (int yaw = 0; yaw < 360; yaw += 30)
        frustums.push_back(frustum_for(eye, {0, float(yaw), 0}));
    culler.cull(eye, frustums[0], out);  // warm-up

    const long before = ::nq::test::g_allocations.load();
    uint32_t total = 0;
    for (int frame = 0; frame < 200; ++frame) {
        const Frustum& f = frustums[size_t(frame) % frustums.size()];
        total += culler.cull(eye + glm::vec3(float(frame), 0, 0), f, out);
        total += start_culler.cull(start_eye, f, start_out);
        culler.box_potentially_visible(eye - 16.0f, eye + 16.0f);
    }
    EXPECT_EQ(::nq::test::g_allocations.load(), before);
    EXPECT_GT(total, 0u);
    // The counter works: a vector allocates.
    { std::vector<int> v(3); }
    EXPECT_GT(::nq::test::g_allocations.load(), before);
}

// The synthetic box rooms (BSP29, BSP2, 2PSB, a missing texture, no PVS): from the player start
// the six room faces are visible and the crate (model 1) is not part of the world list.
TEST(RenderWorldCuller, SyntheticBoxRoomsInEveryFormat) {
    for (const test::SeedFile& seed : test::synthetic_bsp_seeds()) {
        auto bsp = parse_bsp(seed.bytes, seed.name);
        ASSERT_TRUE(bsp) << bsp.error().to_string();
        const auto data = BrushModelData::build(std::move(*bsp));
        WorldCuller culler(data->bsp());
        const glm::vec3 eye(test::box_room::kPlayerStart[0], test::box_room::kPlayerStart[1],
                            test::box_room::kPlayerStart[2]);
        const std::vector<uint32_t> visible = cull(culler, eye, Frustum{});
        EXPECT_EQ(culler.eye_leaf(), test::box_room::kRoomLeaf) << seed.name;
        ASSERT_EQ(visible.size(), size_t{test::box_room::kFacesPerBox}) << seed.name;
        const BspModel& world = data->bsp().models[0];
        for (uint32_t f : visible) EXPECT_LT(f, world.first_face + world.num_faces) << seed.name;
        // Culling works per leaf: the room is one leaf, so any view from inside keeps it whole.
        EXPECT_EQ(cull(culler, eye, frustum_for(eye, {89, 0, 0})).size(), visible.size());
    }
}

TEST(RenderWorldCuller, ShortOutputIsCutToFit) {
    const MapFixture map = load("maps/start.bsp");
    WorldCuller culler(map.bsp());
    std::vector<uint32_t> out(5);
    EXPECT_EQ(culler.cull(map.player_start(), Frustum{}, out), 5u);
}

}  // namespace
}  // namespace nq

// SceneBuilder flags an alias entity NQR_ENTITY_OUTSIDE_VIEW (drawers skip it) when its radius
// sphere or the box of this frame's two poses, placed, lies outside the view. Checked against
// the entities' real vertices over both demos: a flagged entity has every vertex of its blended
// pose behind one side plane (nothing of it can be on screen), and the pose boxes flag
// entities the spheres alone keep. The warm-up frame holds everything the level can show.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "app/frame/scene_builder.h"
#include "support/engine_demo_replay.h"
#include "render/alias_model.h"
#include "render/frustum.h"

namespace nq {
namespace {

struct CullingReport {
    size_t alias_entities = 0;
    size_t flagged = 0;
    size_t flagged_by_pose_only = 0;  // the radius sphere reached into the view
    size_t flagged_with_a_vertex_in_view = 0;
    std::string first_wrong;
};

bool all_behind_one_plane(const Frustum& f, const std::vector<glm::vec3>& points) {
    for (uint32_t i = 0; i < f.num_planes; ++i) {
        const FrustumPlane& p = f.planes[i];
        if (std::all_of(points.begin(), points.end(), [&](const glm::vec3& q) {
                return glm::dot(p.normal, q) - p.dist < 0.0f;
            })) {
            return true;
        }
    }
    return false;
}

CullingReport play_and_check(const std::string& demo) {
    Vfs vfs = test::mount_lq1();
    test::DemoReplay replay(vfs, demo + ".dem");
    SceneBuilder scene;
    uint32_t bound_generation = 0;
    CullingReport r;
    double time = 0;
    for (uint64_t frame = 1;; ++frame) {
        const bool ready = replay.play_to(frame);
        if (replay.frames() < frame) break;  // the demo ended
        if (!ready) continue;
        if (replay.client().generation() != bound_generation) {
            bound_generation = replay.client().generation();
            scene.bind_level(replay.level());
        }
        CameraSetup camera;
        camera.origin = {replay.view().origin[0], replay.view().origin[1], replay.view().origin[2]};
        camera.angles = {replay.view().angles[0], replay.view().angles[1], replay.view().angles[2]};
        time += 0.01;
        const nqr_frame& f =
            scene.build(replay.level(), replay.client(), replay.view(), camera, time, 0.01f);
        const Frustum frustum =
            Frustum::sides_from_view_projection(load_matrix(f.camera->view_projection));
        for (uint32_t i = 0; i < f.num_alias_entities; ++i) {
            const nqr_entity& e = *f.alias_entities[i];
            const RenderModel* model = replay.level().models().get(e.model);
            if (!model || !model->alias_data() || (e.flags & NQR_ENTITY_VIEWMODEL)) continue;
            ++r.alias_entities;
            if ((e.flags & NQR_ENTITY_OUTSIDE_VIEW) == 0) continue;
            ++r.flagged;
            const float radius = std::max(model->abi()->radius, 1.0f) * std::max(e.scale, 1.0f);
            if (!frustum.sphere_outside(glm::vec3(e.origin[0], e.origin[1], e.origin[2]), radius)) {
                ++r.flagged_by_pose_only;
            }
            if (!all_behind_one_plane(
                    frustum, test::blended_world_vertices(model->alias_data()->abi(), e)) &&
                r.flagged_with_a_vertex_in_view++ == 0) {
                r.first_wrong = demo + " frame " + std::to_string(frame) + " entity " +
                                std::to_string(e.number) + " (" + model->name() + ")";
            }
        }
    }
    return r;
}

TEST(EngineSceneCulling, FlaggedEntitiesHaveNothingInViewAndPoseBoxesCullMore) {
    for (const std::string demo : {"demo", "demo2"}) {
        const CullingReport r = play_and_check(demo);
        EXPECT_GT(r.alias_entities, 10000u) << demo;
        EXPECT_EQ(r.flagged_with_a_vertex_in_view, 0u) << r.first_wrong;
        // The pose boxes find a good share of the off-screen entities the spheres keep.
        EXPECT_GT(r.flagged_by_pose_only, r.alias_entities / 50) << demo;
        EXPECT_GT(r.flagged, r.flagged_by_pose_only) << demo;
        std::printf(
            "%s: %zu alias entities, %zu flagged outside the view, %zu by the pose box only\n",
            demo.c_str(), r.alias_entities, r.flagged, r.flagged_by_pose_only);
    }
}

// The warm-up frame drawn at level load holds everything the level can show: every world
// surface (the BSP's own face count), one entity per alias and sprite model the level loaded
// (counted by file name), each in front of the camera, a particle and a dynamic light.
TEST(EngineSceneCulling, WarmUpFrameHoldsEveryWorldSurfaceAndOneEntityPerModel) {
    Vfs vfs = test::mount_lq1();
    test::DemoReplay replay(vfs, "demo.dem");
    uint64_t frame = 1;
    while (!replay.play_to(frame) && replay.frames() >= frame) ++frame;
    ASSERT_TRUE(replay.level().loaded());
    size_t mdl = 0, spr = 0;
    for (const auto& model : replay.level().models().models()) {
        const std::string& name = model->name();
        if (name.size() > 4 && name.compare(name.size() - 4, 4, ".mdl") == 0) ++mdl;
        if (name.size() > 4 && name.compare(name.size() - 4, 4, ".spr") == 0) ++spr;
    }
    ASSERT_GT(mdl, 10u);
    ASSERT_GT(spr, 0u);

    SceneBuilder scene;
    scene.bind_level(replay.level());
    CameraSetup camera;
    camera.origin = {100, -50, 30};
    camera.angles = {10, 135, 0};
    const nqr_frame& f = scene.build_warm_up(replay.level(), camera);
    EXPECT_EQ(f.world, replay.level().models().world()->id());
    EXPECT_EQ(f.num_visible_surfaces, replay.level().world_bsp()->models[0].num_faces);
    EXPECT_EQ(f.num_alias_entities, mdl);
    EXPECT_EQ(f.num_sprite_entities, spr);
    const Frustum frustum =
        Frustum::sides_from_view_projection(load_matrix(f.camera->view_projection));
    for (uint32_t i = 0; i < f.num_alias_entities; ++i) {
        const nqr_entity& e = *f.alias_entities[i];
        EXPECT_FALSE(frustum.sphere_outside(glm::vec3(e.origin[0], e.origin[1], e.origin[2]), 1));
        EXPECT_EQ(e.flags & (NQR_ENTITY_OUTSIDE_VIEW | NQR_ENTITY_OCCLUDED), 0u);
    }
    EXPECT_EQ(f.num_particles, 1u);
    EXPECT_EQ(f.num_dlights, 1u);
}

}  // namespace
}  // namespace nq

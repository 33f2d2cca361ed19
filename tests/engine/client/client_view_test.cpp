// The camera and the view model: eye height, demo view angles (interpolated the short way),
// punch angles, death roll, bob, stair smoothing, the weapon, intermission, the contents hook,
// and the renderer's entity list.
#include <gtest/gtest.h>

#include <cmath>

#include "client/client_math.h"
#include "client/nqr_export.h"
#include "client/view.h"
#include "client/visible_entities.h"
#include "client_test_fixture.h"

namespace nq {
namespace {

using namespace protocol;

constexpr int kPlayer = 1;
constexpr int kWeapon = 3;  // "progs/v_shot.mdl"

class View : public ::testing::Test {
  protected:
    void SetUp() override {
        svc::SetView setview;
        setview.entity = kPlayer;
        test::apply_all(client, {test::server_info({"maps/x.bsp", "progs/player.mdl",
                                                    "progs/v_shot.mdl", "progs/torch.mdl"}),
                                 test::baseline(kPlayer, 2, {}), setview});
        std::vector<ModelInfo> info(client.model_names().size());
        info[2] = info[3] = info[4] = test::alias_info(8);
        client.set_model_info(info);
        data.health = 100;
        data.weapon = kWeapon;
        data.weapon_frame = 2;
        data.bits = SU_ITEMS | SU_WEAPON | SU_WEAPONFRAME | SU_ONGROUND;
    }
    // One demo block: header angles, then a server frame placing the player.
    void frame(float time, const Vec3& origin, const Vec3& view_angles) {
        client.receive_block_angles(view_angles);
        test::apply_all(client, {svc::Time{time}, data, test::origin_update(kPlayer, origin)});
        client.set_time(time);
        client.prepare_frame(LerpMode::Interpolate);
    }
    ClientState client;
    svc::ClientData data;
    ViewState state;
    ViewSettings still = [] {
        ViewSettings s;
        s.bob = false;
        s.roll = false;
        return s;
    }();
};

TEST_F(View, EyeIsViewHeightAboveTheEntityWithRecordedAngles) {
    frame(1.0f, {100, 200, 50}, {10, 90, 0});
    ViewResult v = compute_view(client, state, still);
    EXPECT_EQ(v.origin, (Vec3{100, 200, 50 + 22}));  // default view height 22
    EXPECT_EQ(v.angles, (Vec3{10, 90, 0}));
    EXPECT_FALSE(v.intermission);
    data.view_height = 30;
    data.bits |= SU_VIEWHEIGHT | SU_PUNCH1;
    data.punch_angle = {-2, 0, 0};
    frame(1.1f, {100, 200, 50}, {10, 90, 0});
    v = compute_view(client, state, still);
    EXPECT_EQ(v.origin[2], 80.0f);
    EXPECT_EQ(v.angles, (Vec3{8, 90, 0}));               // the kick moves the camera
    EXPECT_EQ(v.view_model.angles, (Vec3{-10, 90, 0}));  // but not the gun
}

TEST_F(View, DemoAnglesInterpolateTheShortWay) {
    frame(1.0f, {0, 0, 0}, {0, 350, 0});
    frame(1.1f, {0, 0, 0}, {0, 10, 0});
    client.set_time(1.05);
    client.prepare_frame(LerpMode::Interpolate);
    ViewResult v = compute_view(client, state, still);
    EXPECT_NEAR(angle_mod(v.angles[1]), 0.0f, 1e-3);
    client.set_time(1.075);
    client.prepare_frame(LerpMode::Interpolate);
    EXPECT_NEAR(compute_view(client, state, still).angles[1], 365.0f, 1e-3);
}

TEST_F(View, ViewModelSitsAtTheEyeWithTheClientdataWeapon) {
    frame(1.0f, {0, 0, 0}, {0, 45, 0});
    ViewResult v = compute_view(client, state, still);
    ASSERT_TRUE(v.view_model.visible);
    EXPECT_EQ(v.view_model.model, kWeapon);
    EXPECT_EQ(v.view_model.frame, 2);
    EXPECT_EQ(v.view_model.origin, (Vec3{0, 0, 22 + 2}));  // the eye, lifted 2 units
    VisibleEntityList list(8);
    collect_visible_entities(client, v, list);
    ASSERT_EQ(list.size(), 1u);  // the player entity itself is never listed
    const VisibleEntity& gun = list.entities()[0];
    EXPECT_EQ(gun.flags, kVisibleViewModel);
    EXPECT_EQ(gun.model, kWeapon);
    EXPECT_EQ(gun.pose, (PoseBlend{2, 2, 1.0f}));
    // Dead, invisible, or no weapon: no view model.
    data.health = 0;
    frame(1.1f, {0, 0, 0}, {0, 45, 0});
    v = compute_view(client, state, still);
    EXPECT_FALSE(v.view_model.visible);
    EXPECT_EQ(v.angles[2], 80.0f);  // the dead lie on their side
    data.health = 50;
    data.items = kItemInvisibility;
    frame(1.2f, {0, 0, 0}, {0, 45, 0});
    EXPECT_FALSE(compute_view(client, state, still).view_model.visible);
}

TEST_F(View, BobAndRollFollowVelocity) {
    data.bits |= SU_VELOCITY1 | SU_VELOCITY2;
    data.velocity = {0, 320, 0};
    frame(1.0f, {0, 0, 0}, {0, 0, 0});
    frame(1.1f, {0, 0, 0}, {0, 0, 0});
    ViewSettings settings;
    const float bob = view_bob(settings, client.time(), client.player().velocity);
    EXPECT_NE(bob, 0.0f);
    EXPECT_GE(bob, -7.0f);
    EXPECT_LE(bob, 4.0f);
    ViewResult v = compute_view(client, state, settings);
    EXPECT_FLOAT_EQ(v.origin[2], 22 + bob);
    // Moving left (+Y) at yaw 0 at more than cl_rollspeed rolls by cl_rollangle, to the left.
    EXPECT_FLOAT_EQ(v.angles[2], -2.0f);
    EXPECT_EQ(view_bob(settings, 0.3, {0, 0, 0}), 0.0f);
}

TEST_F(View, StairClimbsAreSmoothed) {
    frame(1.0f, {0, 0, 0}, {0, 0, 0});
    compute_view(client, state, still);
    frame(1.1f, {0, 0, 16}, {0, 0, 0});  // a 16-unit step up while on the ground
    // The smoothed eye rises 80 units per second: 8 units in this 0.1 s frame.
    EXPECT_FLOAT_EQ(compute_view(client, state, still).origin[2], 16 + 22 - 8);
    frame(1.2f, {0, 0, 16}, {0, 0, 0});
    EXPECT_FLOAT_EQ(compute_view(client, state, still).origin[2], 16 + 22);
    frame(1.3f, {0, 0, 60}, {0, 0, 0});  // but never lags more than 12 units
    EXPECT_FLOAT_EQ(compute_view(client, state, still).origin[2], 60 + 22 - 12);
}

TEST_F(View, IntermissionUsesTheEntityOriginAndAngles) {
    svc::EntityUpdate spot = test::origin_update(kPlayer, {500, 600, 700});
    spot.bits |= U_ANGLE1 | U_ANGLE2;
    spot.angles = {15, 180, 0};
    test::apply_all(client, {svc::Time{1.0f}, data, spot, svc::Intermission{}});
    client.set_time(1.0);
    client.prepare_frame(LerpMode::Interpolate);
    ViewResult v = compute_view(client, state, still);
    EXPECT_TRUE(v.intermission);
    EXPECT_EQ(v.origin, (Vec3{500, 600, 700}));
    EXPECT_EQ(v.angles, (Vec3{15, 180, 0}));
    EXPECT_FALSE(v.view_model.visible);
    EXPECT_EQ(client.intermission(), Intermission::Intermission);
}

TEST_F(View, ContentsHookDecidesUnderwater) {
    frame(1.0f, {0, 0, 0}, {0, 0, 0});
    ViewSettings settings = still;
    settings.contents_at = [](void* user, const Vec3& at) {
        *static_cast<Vec3*>(user) = at;
        return kContentsWater;
    };
    Vec3 asked{};
    settings.contents_user = &asked;
    ViewResult v = compute_view(client, state, settings);
    EXPECT_TRUE(v.underwater);
    EXPECT_EQ(v.eye_contents, kContentsWater);
    EXPECT_EQ(asked, v.origin);                                   // asked about the eye
    EXPECT_FALSE(compute_view(client, state, still).underwater);  // no hook: unknown
}

TEST_F(View, StaticsAndPlayerColoursReachTheList) {
    svc::SpawnStatic torch;
    torch.state.model = 4;
    torch.state.origin = {1, 2, 3};
    svc::UpdateColors colors;
    colors.client = 0;
    colors.colors = (4 << 4) | 13;
    svc::EntityUpdate other = test::origin_update(2, {9, 9, 9});
    other.bits |= U_MODEL | U_COLORMAP;
    other.model = 2;
    other.colormap = 1;  // wears player 1's colours
    test::apply_all(client, {torch, colors});
    client.receive_block_angles({0, 0, 0});
    test::apply_all(client, {svc::Time{1.0f}, data, test::origin_update(kPlayer, {}), other});
    client.set_time(1.0);
    client.prepare_frame(LerpMode::Interpolate);
    VisibleEntityList list(8);
    collect_visible_entities(client, compute_view(client, state, still), list);
    ASSERT_EQ(list.size(), 3u);  // entity 2, the torch, the view model
    const VisibleEntity& e = list.entities()[0];
    EXPECT_EQ(e.number, 2u);
    EXPECT_TRUE(e.has_translation);
    EXPECT_EQ(e.top_color, 4);
    EXPECT_EQ(e.bottom_color, 13);
    const VisibleEntity& s = list.entities()[1];
    EXPECT_EQ(s.flags, kVisibleStatic);
    EXPECT_EQ(s.origin, (Vec3{1, 2, 3}));
    EXPECT_GE(s.number, client.entity_slots());

    nqr_entity out{};
    export_entity(e, 77, out);
    EXPECT_EQ(out.size, sizeof(nqr_entity));
    EXPECT_EQ(out.number, 2u);
    EXPECT_EQ(out.model, 77u);
    EXPECT_EQ(out.origin[0], 9.0f);
    EXPECT_EQ(out.top_color, 4);
    EXPECT_EQ(out.has_translation, 1);
    EXPECT_EQ(static_cast<uint32_t>(kVisibleViewModel),
              static_cast<uint32_t>(NQR_ENTITY_VIEWMODEL));
    EXPECT_EQ(static_cast<uint32_t>(kVisibleStatic), static_cast<uint32_t>(NQR_ENTITY_STATIC));
    EXPECT_EQ(static_cast<uint32_t>(kVisibleTemp), static_cast<uint32_t>(NQR_ENTITY_TEMP));

    nqr_camera camera{};
    ViewResult v = compute_view(client, state, still);
    export_camera_pose(v, camera);
    EXPECT_EQ(camera.origin[2], 22.0f);
    EXPECT_FLOAT_EQ(camera.forward[0], 1.0f);  // yaw 0 looks along +X
    EXPECT_FLOAT_EQ(camera.right[1], -1.0f);   // +Y is left
    EXPECT_FLOAT_EQ(camera.up[2], 1.0f);
}

TEST(VisibleList, FullListCountsWhatItDrops) {
    VisibleEntityList list(2);
    EXPECT_TRUE(list.push({}));
    EXPECT_TRUE(list.push({}));
    EXPECT_FALSE(list.push({}));
    EXPECT_EQ(list.size(), 2u);
    EXPECT_EQ(list.dropped(), 1u);
    list.clear();
    EXPECT_EQ(list.size(), 0u);
}

}  // namespace
}  // namespace nq

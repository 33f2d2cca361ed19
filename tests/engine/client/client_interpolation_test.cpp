// Interpolation and animation with synthetic messages: origin and angle lerp between the two
// latest updates, snapping (U_NOLERP, teleports, first sight), baseline deltas, entities that
// drop out of the message, frame blending, frame and skin groups, U_LERPFINISH.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "client/animation.h"
#include "client/client_math.h"
#include "client/visible_entities.h"
#include "client_test_fixture.h"
#include "support/raw_bytes.h"

namespace nq {
namespace {

using test::read_le32;
using test::read_lef32;

using namespace protocol;

constexpr int kEntity = 5;
constexpr int kModel = 2;  // "progs/thing.mdl"

// A client that knows a map and one model, with entity 5's baseline at the world origin.
class Interpolation : public ::testing::Test {
  protected:
    void SetUp() override {
        test::apply_all(client, {test::server_info({"maps/test.bsp", "progs/thing.mdl"}),
                                 test::baseline(kEntity, kModel, {0, 0, 0})});
        std::vector<ModelInfo> info(client.model_names().size());
        info[kModel] = test::alias_info(4, {{0.1f, 0.3f, 0.35f}});
        client.set_model_info(info);
    }
    // A server frame at `time` carrying `updates`, then a client frame at `client_time`.
    void server_frame(float time, std::vector<ServerMessage> updates) {
        std::vector<ServerMessage> all{svc::Time{time}};
        all.insert(all.end(), updates.begin(), updates.end());
        test::apply_all(client, all);
    }
    void client_frame(double time) {
        client.set_time(time);
        client.prepare_frame(LerpMode::Interpolate);
    }
    const ClientEntity& ent() { return *client.entity(kEntity); }

    ClientState client;
};

TEST_F(Interpolation, OriginLerpsBetweenTheTwoLatestUpdates) {
    server_frame(1.0f, {test::origin_update(kEntity, {0, 0, 0})});
    client_frame(1.0);
    server_frame(1.1f, {test::origin_update(kEntity, {10, 0, 0})});
    client_frame(1.05);
    EXPECT_NEAR(client.lerp_fraction(), 0.5f, 1e-5);
    EXPECT_NEAR(ent().origin[0], 5.0f, 1e-4);
    EXPECT_TRUE(ent().visible);
    client_frame(1.075);
    EXPECT_NEAR(ent().origin[0], 7.5f, 1e-4);
}

TEST_F(Interpolation, ClockOutsideTheIntervalIsPulledBackAndClamped) {
    server_frame(1.0f, {test::origin_update(kEntity, {0, 0, 0})});
    client_frame(1.0);
    server_frame(1.1f, {test::origin_update(kEntity, {10, 0, 0})});
    client_frame(1.5);  // far past the latest message: time returns to it, no extrapolation
    EXPECT_NEAR(client.time(), 1.1, 1e-6);
    EXPECT_EQ(ent().origin[0], 10.0f);
    client_frame(0.5);  // far before: back to the older message
    EXPECT_NEAR(client.time(), 1.0, 1e-6);
    EXPECT_EQ(ent().origin[0], 0.0f);
}

TEST_F(Interpolation, SnapModeJumpsToTheLatestMessage) {
    server_frame(1.0f, {test::origin_update(kEntity, {0, 0, 0})});
    client_frame(1.0);
    server_frame(1.1f, {test::origin_update(kEntity, {10, 0, 0})});
    client.set_time(1.01);
    client.prepare_frame(LerpMode::Snap);
    EXPECT_EQ(client.time(), static_cast<double>(1.1f));
    EXPECT_EQ(ent().origin[0], 10.0f);
}

TEST_F(Interpolation, AnglesLerpTheShortWayAround) {
    svc::EntityUpdate turn = test::origin_update(kEntity, {0, 0, 0});
    turn.bits |= U_ANGLE2;
    turn.angles = {0, 359, 0};
    server_frame(1.0f, {turn});
    client_frame(1.0);
    turn.angles = {0, 1, 0};
    server_frame(1.1f, {turn});
    client_frame(1.025);
    EXPECT_NEAR(ent().angles[1], 359.5f, 1e-3);  // not 269.5: through 0, not through 180
    client_frame(1.05);
    EXPECT_NEAR(angle_mod(ent().angles[1]), 0.0f, 1e-3);
    EXPECT_NEAR(lerp_angle(1, 359, 0.5f), 0.0f, 1e-4);
    EXPECT_NEAR(lerp_angle(-170, 170, 0.5f), -180.0f, 1e-4);
}

TEST_F(Interpolation, NoLerpUpdatesSnap) {
    server_frame(1.0f, {test::origin_update(kEntity, {0, 0, 0})});
    client_frame(1.0);
    svc::EntityUpdate step = test::origin_update(kEntity, {10, 0, 0});
    step.bits |= U_NOLERP;
    server_frame(1.1f, {step});
    client_frame(1.05);
    EXPECT_EQ(ent().origin[0], 10.0f);
}

TEST_F(Interpolation, LongMovesAreTeleportsNotMotion) {
    server_frame(1.0f, {test::origin_update(kEntity, {0, 0, 0})});
    client_frame(1.0);
    server_frame(1.1f, {test::origin_update(kEntity, {0, 101, 0})});
    client_frame(1.05);
    EXPECT_EQ(ent().origin[1], 101.0f);
    server_frame(1.2f, {test::origin_update(kEntity, {0, 201, 0})});  // exactly 100: a motion
    client_frame(1.15);
    EXPECT_NEAR(ent().origin[1], 151.0f, 1e-3);
}

TEST_F(Interpolation, FirstSightAndReturnAfterAGapSnap) {
    server_frame(1.0f, {});
    client_frame(1.0);
    server_frame(1.1f, {test::origin_update(kEntity, {10, 0, 0})});  // first update ever
    client_frame(1.05);
    EXPECT_EQ(ent().origin[0], 10.0f);
    server_frame(1.2f, {});  // not in this message: not drawn
    client_frame(1.15);
    EXPECT_FALSE(ent().visible);
    server_frame(1.3f, {test::origin_update(kEntity, {30, 0, 0})});
    client_frame(1.25);
    EXPECT_TRUE(ent().visible);
    EXPECT_EQ(ent().origin[0], 30.0f);  // the previous update is not the message before
}

TEST_F(Interpolation, FieldsNotSentComeFromTheBaseline) {
    svc::SpawnBaseline b = test::baseline(7, kModel, {1, 2, 3});
    b.state.frame = 2;
    b.state.skin = 1;
    b.state.angles = {0, 90, 0};
    test::apply_all(client, {b});
    svc::EntityUpdate u;
    u.entity = 7;
    u.bits = U_SIGNAL | U_ORIGIN2;
    u.origin = {0, 50, 0};
    server_frame(1.0f, {u});
    client_frame(1.0);
    const ClientEntity& e = *client.entity(7);
    EXPECT_EQ(e.origin, (Vec3{1, 50, 3}));
    EXPECT_EQ(e.angles, (Vec3{0, 90, 0}));
    EXPECT_EQ(e.model, kModel);
    EXPECT_EQ(e.frame, 2);
    EXPECT_EQ(e.skin, 1);
    EXPECT_EQ(e.effects, 0);
    // FitzQuake's high bytes combine with the baseline's low byte.
    u.bits = U_SIGNAL | U_MOREBITS | U_EXTEND1 | U_FRAME2;
    u.frame = 1 << 8;
    server_frame(1.1f, {u});
    EXPECT_EQ(client.entity(7)->frame, (1 << 8) | 2);
}

TEST_F(Interpolation, OnlyEntitiesInTheLatestMessageAreListed) {
    test::apply_all(client, {test::baseline(6, kModel, {5, 5, 5})});
    server_frame(1.0f,
                 {test::origin_update(kEntity, {0, 0, 0}), test::origin_update(6, {5, 5, 5})});
    client_frame(1.0);
    server_frame(1.1f, {test::origin_update(kEntity, {1, 0, 0})});
    client_frame(1.05);
    VisibleEntityList list(16);
    ViewState vs;
    collect_visible_entities(client, compute_view(client, vs), list);
    ASSERT_EQ(list.size(), 1u);
    EXPECT_EQ(list.entities()[0].number, static_cast<uint32_t>(kEntity));
}

svc::EntityUpdate frame_update(int frame) {
    svc::EntityUpdate u = test::origin_update(kEntity, {0, 0, 0});
    u.bits |= U_FRAME;
    u.frame = frame;
    return u;
}

TEST_F(Interpolation, FrameChangeBlendsOverATenthOfASecond) {
    server_frame(1.0f, {frame_update(0)});
    client_frame(1.0);
    server_frame(1.1f, {frame_update(1)});
    client_frame(1.1);  // the change is seen at client time 1.1
    server_frame(1.2f, {frame_update(1)});
    client_frame(1.15);
    PoseBlend blend =
        resolve_frame_blend(client.model_info(kModel), ent().anim.lerp, client.time());
    EXPECT_EQ(blend.pose0, 0u);
    EXPECT_EQ(blend.pose1, 1u);
    EXPECT_NEAR(blend.lerp, 0.5f, 1e-4);
    client_frame(1.2);  // the blend is complete
    blend = resolve_frame_blend(client.model_info(kModel), ent().anim.lerp, client.time());
    EXPECT_EQ(blend.pose1, 1u);
    EXPECT_FLOAT_EQ(blend.lerp, 1.0f);
    blend = resolve_frame_blend(client.model_info(kModel), ent().anim.lerp, 1.3);
    EXPECT_EQ(blend, (PoseBlend{1, 1, 1.0f}));  // and then the frame just stands
}

TEST_F(Interpolation, LerpFinishSetsTheBlendTime) {
    server_frame(1.0f, {frame_update(0)});
    client_frame(1.0);
    svc::EntityUpdate u = frame_update(2);
    u.bits |= U_MOREBITS | U_EXTEND1 | U_LERPFINISH;
    u.lerp_finish = 0.2f;  // the next think comes 0.2 s after this message
    server_frame(1.1f, {u});
    client_frame(1.1);
    EXPECT_NEAR(ent().anim.lerp.interval, 0.2, 1e-6);
    PoseBlend blend = resolve_frame_blend(client.model_info(kModel), ent().anim.lerp, 1.15);
    EXPECT_EQ(blend.pose0, 0u);
    EXPECT_EQ(blend.pose1, 2u);
    EXPECT_NEAR(blend.lerp, 0.25f, 1e-4);
}

TEST_F(Interpolation, ModelChangeDoesNotBlend) {
    server_frame(1.0f, {frame_update(0)});
    client_frame(1.0);
    svc::EntityUpdate u = frame_update(3);
    u.bits |= U_MODEL;
    u.model = 1;  // the map's model: another model altogether
    server_frame(1.1f, {u});
    client_frame(1.1);
    EXPECT_EQ(ent().anim.lerp.previous_frame, 3);
}

// ---- the resolution functions alone ------------------------------------------------------

TEST(Animation, FrameGroupsCycleByCumulativeIntervals) {
    // Frames 0..3 single (poses 0..3); frame 4 a group of poses 4, 5, 6 ending at 0.1, 0.3, 0.35.
    ModelInfo info = test::alias_info(4, {{0.1f, 0.3f, 0.35f}});
    FrameLerp lerp;
    lerp.frame = lerp.previous_frame = 4;
    EXPECT_EQ(resolve_frame_blend(info, lerp, 0.05), (PoseBlend{6, 4, 0.5f}));
    PoseBlend at = resolve_frame_blend(info, lerp, 0.2);  // halfway through pose 5
    EXPECT_EQ(at.pose0, 4u);
    EXPECT_EQ(at.pose1, 5u);
    EXPECT_NEAR(at.lerp, 0.5f, 1e-4);
    at = resolve_frame_blend(info, lerp, 0.35 * 10 + 0.325);  // ten cycles later, pose 6
    EXPECT_EQ(at.pose1, 6u);
    EXPECT_NEAR(at.lerp, 0.5f, 1e-3);
    // Out-of-range frames show frame 0, as Quake does.
    lerp.frame = lerp.previous_frame = 99;
    EXPECT_EQ(resolve_frame_blend(info, lerp, 1.0), (PoseBlend{0, 0, 1.0f}));
}

TEST(Animation, FrameChangeBlendsFromThePoseShownAtTheChange) {
    ModelInfo info = test::alias_info(4, {{0.1f, 0.3f, 0.35f}});
    FrameLerp lerp;
    lerp.previous_frame = 4;  // the group, showing pose 5 at t = 0.2
    lerp.frame = 1;
    lerp.frame_start = 0.2;
    PoseBlend b = resolve_frame_blend(info, lerp, 0.225);
    EXPECT_EQ(b.pose0, 5u);
    EXPECT_EQ(b.pose1, 1u);
    EXPECT_NEAR(b.lerp, 0.25f, 1e-4);
}

TEST(Animation, SpritesShowOneImageAndSkinsCycle) {
    ModelInfo sprite;
    sprite.kind = ModelKind::Sprite;
    sprite.frames = {{0, 1, {}}, {1, 2, {0.5f, 1.0f}}};
    FrameLerp lerp;
    lerp.frame = 1;
    lerp.previous_frame = 0;
    lerp.frame_start = 0.0;
    EXPECT_EQ(resolve_frame_blend(sprite, lerp, 0.75), (PoseBlend{2, 2, 1.0f}));

    ModelInfo skins = test::alias_info(1);
    skins.skins = {{0, 1, {}}, {0, 3, {0.1f, 0.2f, 0.3f}}};
    EXPECT_EQ(resolve_skin_image(skins, 1, 0.05), 0u);
    EXPECT_EQ(resolve_skin_image(skins, 1, 0.25), 2u);
    EXPECT_EQ(resolve_skin_image(skins, 1, 0.35), 0u);
    EXPECT_EQ(resolve_skin_image(skins, 7, 0.25), 0u);  // no such skin: skin 0
}

// ---- model information from the real files, checked against an independent walk ------------

// Walks an MDL by its documented layout: 84-byte header, skins, st verts (12 bytes each),
// triangles (16), then frames: type 0 = one pose (8 + 16 + 4 * verts bytes), else a group.
std::vector<AnimationGroup> walk_mdl_frames(const std::vector<uint8_t>& b) {
    const int skins = read_le32(b, 48), width = read_le32(b, 52), height = read_le32(b, 56);
    const int verts = read_le32(b, 60), tris = read_le32(b, 64), frames = read_le32(b, 68);
    size_t at = 84;
    for (int i = 0; i < skins; ++i) {
        const int type = read_le32(b, at);
        at += 4;
        const int n = type == 0 ? 1 : read_le32(b, at);
        if (type != 0) at += 4 + 4 * static_cast<size_t>(n);
        at += static_cast<size_t>(n) * static_cast<size_t>(width * height);
    }
    at += static_cast<size_t>(verts) * 12 + static_cast<size_t>(tris) * 16;
    const size_t pose_bytes = 8 + 16 + 4 * static_cast<size_t>(verts);
    std::vector<AnimationGroup> out;
    uint32_t pose = 0;
    for (int f = 0; f < frames; ++f) {
        const int type = read_le32(b, at);
        at += 4;
        if (type == 0) {
            out.push_back({pose++, 1, {}});
            at += pose_bytes;
            continue;
        }
        const int n = read_le32(b, at);
        AnimationGroup g{pose, static_cast<uint32_t>(n), {}};
        for (int i = 0; i < n; ++i) g.intervals.push_back(read_lef32(b, at + 12 + 4 * i));
        at += 12 + 4 * static_cast<size_t>(n) + static_cast<size_t>(n) * pose_bytes;
        pose += static_cast<uint32_t>(n);
        out.push_back(g);
    }
    return out;
}

TEST(ModelInfoFromFiles, FramesPosesAndFlagsMatchTheFiles) {
    for (const char* name : {"progs/flame2.mdl", "progs/player.mdl", "progs/missile.mdl"}) {
        SCOPED_TRACE(name);
        std::vector<uint8_t> bytes = test::load_lq1(name);
        auto mdl = parse_mdl(bytes, name);
        ASSERT_TRUE(mdl.ok()) << mdl.error().to_string();
        ModelInfo info = model_info_from_mdl(mdl.value());
        EXPECT_EQ(info.kind, ModelKind::Alias);
        EXPECT_EQ(info.flags, read_le32(bytes, 76));
        EXPECT_EQ(info.sync_type, read_le32(bytes, 72));
        EXPECT_EQ(info.skins.size(), static_cast<size_t>(read_le32(bytes, 48)));
        std::vector<AnimationGroup> want = walk_mdl_frames(bytes);
        ASSERT_EQ(info.frames.size(), want.size());
        for (size_t i = 0; i < want.size(); ++i) {
            EXPECT_EQ(info.frames[i].first, want[i].first) << i;
            EXPECT_EQ(info.frames[i].count, want[i].count) << i;
            EXPECT_EQ(info.frames[i].intervals, want[i].intervals) << i;
        }
    }
    // flame2.mdl holds two frame groups (14 poses): the second group's poses follow the first.
    ModelInfo flame =
        model_info_from_mdl(parse_mdl(test::load_lq1("progs/flame2.mdl"), "flame2.mdl").value());
    ASSERT_EQ(flame.frames.size(), 2u);
    EXPECT_EQ(flame.frames[0].count + flame.frames[1].count, 14u);
    EXPECT_EQ(flame.frames[1].first, flame.frames[0].count);
    EXPECT_EQ(
        model_info_from_mdl(parse_mdl(test::load_lq1("progs/missile.mdl"), "m").value()).flags &
            kEfRocket,
        kEfRocket);
}

TEST(ModelInfoFromFiles, SpriteFramesCountImages) {
    std::vector<uint8_t> bytes = test::load_lq1("progs/s_explod.spr");
    auto spr = parse_spr(bytes, "s_explod.spr");
    ASSERT_TRUE(spr.ok());
    ModelInfo info = model_info_from_spr(spr.value());
    EXPECT_EQ(info.kind, ModelKind::Sprite);
    EXPECT_FALSE(info.lerp_poses);
    EXPECT_EQ(info.frames.size(), static_cast<size_t>(read_le32(bytes, 24)));  // header numframes
    uint32_t image = 0;
    for (const AnimationGroup& g : info.frames) {
        EXPECT_EQ(g.first, image);
        image += g.count;
    }
}

}  // namespace
}  // namespace nq

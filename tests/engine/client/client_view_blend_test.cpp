// The screen tints (Quake's colour shifts) and the other things damage and pickups leave on
// screen: the damage flash of svc_damage and its decay, the bonus flash of a stuffed "bf", the
// pain face, the inventory's pickup times, and how GLQuake mixes the shifts into one blend.
// Expected values come from Quake's rules (shift = 3 x max(10, (armour + blood) / 2), at most
// 150, falling 150 a second; bonus 50 falling 100 a second; the contents and powerup colours),
// worked out by hand here.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "client/client_state.h"
#include "client/view.h"
#include "client/view_blend.h"
#include "client_test_fixture.h"

namespace nq {
namespace {

using test::apply_all;
using test::server_info;

svc::Damage damage(int armor, int blood) {
    svc::Damage d;
    d.armor = armor;
    d.blood = blood;
    return d;
}

svc::StuffText stuffed(std::string text) {
    svc::StuffText s;
    s.text = std::move(text);
    return s;
}

svc::ClientData client_data(int32_t items, int health = 100) {
    svc::ClientData d;
    d.items = items;
    d.health = health;
    return d;
}

// A client in a level at client time `now`.
void start_level(ClientState& client, double now) {
    apply_all(client, {server_info({"maps/test.bsp"})});
    client.set_time(now);
}

TEST(ScreenFlashes, DamageShiftGrowsWithTheHitAndFallsAt150ASecond) {
    ScreenFlashes flashes;
    flashes.damage(0, 20, 1.0);  // count max(10, 10) = 10: 30
    EXPECT_FLOAT_EQ(flashes.damage_shift(1.0).percent, 30.0f);
    EXPECT_EQ(flashes.damage_shift(1.0).colour, (std::array<float, 3>{255, 0, 0}));
    EXPECT_FLOAT_EQ(flashes.damage_shift(1.1).percent, 15.0f);
    EXPECT_FLOAT_EQ(flashes.damage_shift(1.25).percent, 0.0f);
    EXPECT_FLOAT_EQ(flashes.damage_shift(5.0).percent, 0.0f);

    flashes.damage(0, 60, 2.0);  // count 30: 90
    flashes.damage(0, 60, 2.0);  // 180, capped at 150
    EXPECT_FLOAT_EQ(flashes.damage_shift(2.0).percent, 150.0f);
    EXPECT_FLOAT_EQ(flashes.damage_shift(2.5).percent, 75.0f);
    // A hit on top of a fading flash adds to what is left.
    flashes.damage(4, 4, 2.5);  // count 10: 75 + 30
    EXPECT_FLOAT_EQ(flashes.damage_shift(2.5).percent, 105.0f);
    EXPECT_NEAR(flashes.damage_shift(2.5 + 105.0 / 150.0).percent, 0.0f, 1e-3);
    EXPECT_FLOAT_EQ(flashes.damage_shift(3.5).percent, 0.0f);
}

TEST(ScreenFlashes, DamageColourTellsArmourFromBlood) {
    ScreenFlashes flashes;
    flashes.damage(30, 10, 0);
    EXPECT_EQ(flashes.damage_shift(0).colour, (std::array<float, 3>{200, 100, 100}));
    flashes.damage(10, 30, 0);
    EXPECT_EQ(flashes.damage_shift(0).colour, (std::array<float, 3>{220, 50, 50}));
    flashes.damage(0, 30, 0);
    EXPECT_EQ(flashes.damage_shift(0).colour, (std::array<float, 3>{255, 0, 0}));
}

TEST(ScreenFlashes, AbsurdDamageIsClampedAndTimeGoingBackwardsDecaysNothing) {
    ScreenFlashes flashes;
    flashes.damage(-5, 1 << 30, 10.0);
    EXPECT_FLOAT_EQ(flashes.damage_shift(10.0).percent, 150.0f);
    EXPECT_FLOAT_EQ(flashes.damage_shift(9.0).percent, 150.0f);
    flashes.damage(-100, -100, 20.0);  // both clamp to 0: the minimum count 10, shift 30
    EXPECT_FLOAT_EQ(flashes.damage_shift(20.0).percent, 30.0f);
    EXPECT_TRUE(std::isfinite(flashes.damage_shift(1e300).percent));
}

TEST(ScreenFlashes, PainFaceLastsAFifthOfASecond) {
    ScreenFlashes flashes;
    EXPECT_FALSE(flashes.pain_face(0));
    flashes.damage(0, 5, 3.0);
    EXPECT_TRUE(flashes.pain_face(3.0));
    EXPECT_TRUE(flashes.pain_face(3.19));
    EXPECT_FALSE(flashes.pain_face(3.21));
}

TEST(ScreenFlashes, BonusFlashIsGoldAndFallsAt100ASecond) {
    ScreenFlashes flashes;
    flashes.bonus(4.0);
    EXPECT_EQ(flashes.bonus_shift(4.0), (ColourShift{{215, 186, 69}, 50}));
    EXPECT_FLOAT_EQ(flashes.bonus_shift(4.25).percent, 25.0f);
    EXPECT_FLOAT_EQ(flashes.bonus_shift(4.5).percent, 0.0f);
}

TEST(ClientFlashes, SvcDamageFlashesAndShowsThePainFace) {
    ClientState client;
    start_level(client, 5.0);
    apply_all(client, {damage(0, 40)});  // count 20: 60
    EXPECT_FLOAT_EQ(client.flashes().damage_shift(client.time()).percent, 60.0f);
    EXPECT_TRUE(client.flashes().pain_face(client.time()));
    EXPECT_EQ(client.message_count(protocol::svc_damage), 1u);
}

TEST(ClientFlashes, OnlyTheStuffedCommandBfFlashes) {
    for (const char* text : {"bf\n", "bf", "  bf \n", "echo hi; bf\n", "echo hi\nbf\n"}) {
        ClientState client;
        start_level(client, 2.0);
        apply_all(client, {stuffed(text)});
        EXPECT_FLOAT_EQ(client.flashes().bonus_shift(2.0).percent, 50.0f) << text;
        EXPECT_EQ(client.take_stuff_text().size(), 1u) << "still passed on (and ignored)";
    }
    for (const char* text : {"bfg\n", "echo bf\n", "b f\n", "", "\n;\n", "bf2"}) {
        ClientState client;
        start_level(client, 2.0);
        apply_all(client, {stuffed(text)});
        EXPECT_FLOAT_EQ(client.flashes().bonus_shift(2.0).percent, 0.0f) << text;
    }
}

TEST(ClientFlashes, ANewLevelClearsTheFlashes) {
    ClientState client;
    start_level(client, 5.0);
    apply_all(client, {damage(0, 40), stuffed("bf\n")});
    start_level(client, 5.0);
    EXPECT_FLOAT_EQ(client.flashes().damage_shift(5.0).percent, 0.0f);
    EXPECT_FLOAT_EQ(client.flashes().bonus_shift(5.0).percent, 0.0f);
    EXPECT_FALSE(client.flashes().pain_face(5.0));
}

TEST(ClientItems, PickupTimesAreTheTimeEachBitWasSwitchedOn) {
    ClientState client;
    start_level(client, 1.0);
    apply_all(client, {client_data(kItemShotgun)});
    client.set_time(2.0);
    apply_all(client, {client_data(kItemShotgun | kItemNailgun)});
    client.set_time(3.0);
    apply_all(client, {client_data(kItemShotgun | kItemNailgun | kItemSigil1 << 3)});
    const PlayerState& p = client.player();
    EXPECT_DOUBLE_EQ(p.item_times[0], 1.0);   // kept, not refreshed while held
    EXPECT_DOUBLE_EQ(p.item_times[2], 2.0);   // the nailgun
    EXPECT_DOUBLE_EQ(p.item_times[31], 3.0);  // the fourth sigil, the sign bit
    EXPECT_DOUBLE_EQ(p.item_times[1], 0.0);   // never held
    // Dropped and picked up again: a new time.
    client.set_time(4.0);
    apply_all(client, {client_data(kItemNailgun)});
    client.set_time(5.0);
    apply_all(client, {client_data(kItemShotgun | kItemNailgun)});
    EXPECT_DOUBLE_EQ(client.player().item_times[0], 5.0);
    EXPECT_DOUBLE_EQ(client.player().item_times[2], 2.0);
}

// ------------------------------------------------------------------ the blend

TEST(ViewBlend, NothingWithoutAShift) {
    ClientState client;
    start_level(client, 1.0);
    EXPECT_EQ(view_blend(client, -1).a, 0.0f);  // CONTENTS_EMPTY
    EXPECT_EQ(view_blend(client, -2).a, 0.0f);  // solid
    EXPECT_EQ(view_blend(client, -6).a, 0.0f);  // sky
    EXPECT_EQ(view_blend(client, 0).a, 0.0f);   // unknown
}

TEST(ViewBlend, LiquidsTintTheView) {
    ClientState client;
    start_level(client, 1.0);
    ScreenBlend water = view_blend(client, kContentsWater);
    EXPECT_FLOAT_EQ(water.a, 128.0f / 255.0f);
    EXPECT_FLOAT_EQ(water.r, 130.0f / 255.0f);
    EXPECT_FLOAT_EQ(water.g, 80.0f / 255.0f);
    EXPECT_FLOAT_EQ(water.b, 50.0f / 255.0f);
    ScreenBlend slime = view_blend(client, kContentsSlime);
    EXPECT_FLOAT_EQ(slime.a, 150.0f / 255.0f);
    EXPECT_FLOAT_EQ(slime.g, 25.0f / 255.0f);
    ScreenBlend lava = view_blend(client, kContentsLava);
    EXPECT_FLOAT_EQ(lava.r, 1.0f);
    EXPECT_FLOAT_EQ(lava.g, 80.0f / 255.0f);
}

TEST(ViewBlend, PowerupsInQuakesOrder) {
    EXPECT_EQ(powerup_shift(kItemQuad | kItemSuit | kItemInvisibility),
              (ColourShift{{0, 0, 255}, 30}));
    EXPECT_EQ(powerup_shift(kItemSuit | kItemInvulnerability), (ColourShift{{0, 255, 0}, 20}));
    EXPECT_EQ(powerup_shift(kItemInvisibility | kItemInvulnerability),
              (ColourShift{{100, 100, 100}, 100}));
    EXPECT_EQ(powerup_shift(kItemInvulnerability), (ColourShift{{255, 255, 0}, 30}));
    EXPECT_EQ(powerup_shift(kItemShotgun | kItemKey1).percent, 0.0f);
}

TEST(ViewBlend, ShiftsAreLaidOverOneAnother) {
    // Water (alpha 128/255) then full red damage (alpha 150/255):
    //   a = a1 + a2 (1 - a1); the colour is the water's, then moved toward red by a2 / a.
    std::array<ColourShift, 2> shifts{ColourShift{{130, 80, 50}, 128},
                                      ColourShift{{255, 0, 0}, 150}};
    ScreenBlend blend = mix_colour_shifts(shifts);
    float a1 = 128.0f / 255, a2 = 150.0f / 255;
    float a = a1 + a2 * (1 - a1);
    float share = a2 / a;
    EXPECT_NEAR(blend.a, a, 1e-6);
    EXPECT_NEAR(blend.r, (130 * (1 - share) + 255 * share) / 255, 1e-6);
    EXPECT_NEAR(blend.g, (80 * (1 - share)) / 255, 1e-6);
    EXPECT_NEAR(blend.b, (50 * (1 - share)) / 255, 1e-6);
    // Shifts at zero change nothing, whatever their colour.
    std::array<ColourShift, 3> with_zero{ColourShift{{9, 9, 9}, 0}, shifts[0], shifts[1]};
    ScreenBlend same = mix_colour_shifts(with_zero);
    EXPECT_FLOAT_EQ(same.a, blend.a);
    EXPECT_FLOAT_EQ(same.r, blend.r);
}

TEST(ViewBlend, ClientFlashesDecayToNothing) {
    ClientState client;
    start_level(client, 10.0);
    apply_all(client, {damage(0, 100), client_data(0)});  // 150: a full second to fade
    ScreenBlend hit = view_blend(client, -1);
    EXPECT_FLOAT_EQ(hit.a, 150.0f / 255.0f);
    EXPECT_FLOAT_EQ(hit.r, 1.0f);
    EXPECT_FLOAT_EQ(hit.g, 0.0f);
    client.set_time(10.5);
    EXPECT_FLOAT_EQ(view_blend(client, -1).a, 75.0f / 255.0f);
    client.set_time(11.0);
    EXPECT_EQ(view_blend(client, -1).a, 0.0f);
}

TEST(ViewBlend, IntermissionKeepsOnlyTheContentsShift) {
    ClientState client;
    start_level(client, 10.0);
    apply_all(client, {damage(0, 100), client_data(kItemQuad), stuffed("bf\n")});
    EXPECT_GT(view_blend(client, -1).a, 0.5f);
    apply_all(client, {svc::Intermission{}});
    EXPECT_EQ(view_blend(client, -1).a, 0.0f);
    EXPECT_FLOAT_EQ(view_blend(client, kContentsWater).a, 128.0f / 255.0f);
}

TEST(ViewModelLift, FollowsGLQuakesScreenSizes) {
    EXPECT_EQ(view_model_lift_for(100), 2.0f);
    EXPECT_EQ(view_model_lift_for(110), 1.0f);
    EXPECT_EQ(view_model_lift_for(90), 1.0f);
    EXPECT_EQ(view_model_lift_for(80), 0.5f);
    EXPECT_EQ(view_model_lift_for(120), 0.0f);
    EXPECT_EQ(view_model_lift_for(105), 0.0f);
}

}  // namespace
}  // namespace nq

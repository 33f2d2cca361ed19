// The status bar, inventory, scoreboards, intermission and crosshair as quads (no GL): which
// picture lands where for known client states, on Quake's 320-wide canvases. Positions are
// Quake's (the status bar's numbers at x 24 / 136 / 248, the face at 112, ...); pictures are
// identified by their atlas regions, and the atlas is checked against pictures decoded
// straight from LibreQuake's gfx.wad.
#include <gtest/gtest.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <string>
#include <vector>

#include "hud/big_numbers.h"
#include "hud/hud_canvas.h"
#include "hud/scoreboard.h"
#include "hud/status_bar.h"
#include "support/hud_test_support.h"
#include "support/synth_wad.h"

namespace nq {
namespace {

using namespace test;

constexpr int kW = 320;
constexpr int kH = 200;
constexpr float kBarRow = kH - 24;        // the status bar's row at scale 1
constexpr float kInventoryRow = kH - 48;  // the inventory's

// The quads showing picture `id` (by its atlas region).
std::vector<EmittedQuad> quads_of(const std::vector<EmittedQuad>& quads,
                                  const HudPictures& pictures, PictureId id) {
    std::vector<EmittedQuad> out;
    const AtlasPicture* picture = pictures.find(id);
    if (!picture) return out;
    for (const EmittedQuad& q : quads) {
        if (q.sampling == kSampleFiltered && q.region == picture->region) out.push_back(q);
    }
    return out;
}

// Whether picture `id` is drawn with its top-left corner at (x, y), at its own size * scale.
bool drawn_at(const std::vector<EmittedQuad>& quads, const HudPictures& pictures, PictureId id,
              float x, float y, float scale = 1) {
    const AtlasPicture* picture = pictures.find(id);
    if (!picture) return false;
    for (const EmittedQuad& q : quads_of(quads, pictures, id)) {
        if (q.x0 == x && q.y0 == y && q.x1 == x + picture->width * scale &&
            q.y1 == y + picture->height * scale)
            return true;
    }
    return false;
}

// Glyph quads (texel-exact) as (glyph, x, y).
struct PlacedGlyph {
    int glyph;
    float x, y;
    friend bool operator==(const PlacedGlyph&, const PlacedGlyph&) = default;
};
std::vector<PlacedGlyph> glyphs(const std::vector<EmittedQuad>& quads,
                                const HudPictures& pictures) {
    std::vector<PlacedGlyph> out;
    const AtlasPicture* font = pictures.find(pictures.ids().conchars);
    if (!font) return out;
    float span_u = (font->region.u1 - font->region.u0) / 16;
    float span_v = (font->region.v1 - font->region.v0) / 16;
    for (const EmittedQuad& q : quads) {
        if (q.sampling != kSampleTexelExact) continue;
        int column = static_cast<int>(std::lround((q.region.u0 - font->region.u0) / span_u));
        int row = static_cast<int>(std::lround((q.region.v0 - font->region.v0) / span_v));
        out.push_back({row * 16 + column, q.x0, q.y0});
    }
    return out;
}

bool has_glyph(const std::vector<PlacedGlyph>& placed, int glyph, float x, float y) {
    return std::find(placed.begin(), placed.end(), PlacedGlyph{glyph, x, y}) != placed.end();
}

class HudLayout : public ::testing::Test {
  protected:
    static HudTestData& data() {
        static HudTestData shared;
        return shared;
    }
    const HudPictures& pictures() { return data().pictures; }
    const HudPictureIds& ids() { return data().pictures.ids(); }
};

// ------------------------------------------------------------------ pictures

TEST_F(HudLayout, EveryStatusBarPictureOfLibreQuakeLoads) {
    EXPECT_TRUE(pictures().warnings().empty());
    // Without a filesystem the gfx/*.lmp pictures are missing (the intermission's, then the
    // menu's); everything in gfx.wad is there.
    std::vector<std::string> lmps = {"complete", "inter",    "finale",   "ranking",
                                     "qplaque",  "ttl_main", "mainmenu", "ttl_sgl",
                                     "sp_menu",  "p_option", "p_load",   "p_save"};
    for (int i = 1; i <= kMenuDotFrames; ++i) lmps.push_back("menudot" + std::to_string(i));
    for (int i = 0; i < kMaxHelpPages; ++i) lmps.push_back("help" + std::to_string(i));
    for (std::string& name : lmps) name = "gfx/" + name + ".lmp";
    EXPECT_EQ(pictures().missing(), lmps);
    for (PictureId id : {ids().sbar, ids().ibar, ids().scorebar, ids().disc, ids().colon,
                         ids().slash, ids().face_quad, ids().face_invisible, ids().conchars}) {
        EXPECT_NE(pictures().find(id), nullptr);
    }
    for (const auto& colour : ids().numbers)
        for (PictureId id : colour) EXPECT_NE(pictures().find(id), nullptr);
    for (const auto& frame : ids().weapons)
        for (PictureId id : frame) EXPECT_NE(pictures().find(id), nullptr);
    EXPECT_EQ(pictures().find(ids().complete), nullptr);
    EXPECT_EQ(pictures().find(kNoPicture), nullptr);
}

TEST_F(HudLayout, TheAtlasHoldsThePicturesAsTheWadHasThem) {
    const RgbaImage& atlas = pictures().atlas_image();
    for (auto [name, id] : {std::pair{"num_3", ids().numbers[kWhiteNumbers][3]},
                            std::pair{"anum_minus", ids().numbers[kRedNumbers][kMinusDigit]},
                            std::pair{"face_p2", ids().faces[3][1]},
                            std::pair{"inv_lightng", ids().weapons[kWeaponOwned][6]},
                            std::pair{"sbar", ids().sbar}}) {
        SCOPED_TRACE(name);
        Pic pic = wad_picture(data().wad, name);
        const AtlasPicture* placed = pictures().find(id);
        ASSERT_NE(placed, nullptr);
        ASSERT_EQ(placed->width, pic.width);
        ASSERT_EQ(placed->height, pic.height);
        int left = static_cast<int>(std::lround(placed->region.u0 * atlas.width));
        int top = static_cast<int>(std::lround(placed->region.v0 * atlas.height));
        int mismatches = 0;
        for (int y = 0; y < pic.height; ++y) {
            for (int x = 0; x < pic.width; ++x) {
                const uint8_t* texel =
                    &atlas.rgba[(static_cast<size_t>(top + y) * atlas.width + left + x) * 4];
                uint8_t index = pic.at(x, y);
                bool transparent = index == kTransparentIndex;
                Rgb expected = data().palette.colors[index];
                bool same = transparent ? texel[3] == 0
                                        : texel[3] == 255 && texel[0] == expected.r &&
                                              texel[1] == expected.g && texel[2] == expected.b;
                mismatches += !same;
            }
        }
        EXPECT_EQ(mismatches, 0);
    }
}

TEST(HudPicturesLoading, OddPicturesAreRefusedAndTheRestDrawn) {
    SynthWad synth;
    synth.lumps.push_back(
        {"SBAR", 0x42, 0, write_qpic(320, 24, std::vector<uint8_t>(320 * 24, 7)), {}, {}, {}});
    synth.lumps.push_back({"NUM_0", 0x44, 0, std::vector<uint8_t>(600, 1), {}, {}, {}});  // miptex
    synth.lumps.push_back({"NUM_1",
                           0x42,
                           0,
                           write_qpic(2000, 1, std::vector<uint8_t>(2000, 3)),
                           {},
                           {},
                           {}});  // huge
    std::vector<uint8_t> truncated = write_qpic(24, 24, std::vector<uint8_t>(24 * 24, 5));
    truncated.resize(40);
    synth.lumps.push_back({"NUM_2", 0x42, 0, truncated, {}, {}, {}});
    auto wad = parse_wad(write_wad(synth), "odd.wad");
    ASSERT_TRUE(wad) << wad.error().message;
    HudPictures pictures = HudPictures::load(*wad, lq1_palette(), nullptr);

    EXPECT_NE(pictures.find(pictures.ids().sbar), nullptr);
    EXPECT_EQ(pictures.find(pictures.ids().numbers[0][0]), nullptr);
    EXPECT_EQ(pictures.find(pictures.ids().numbers[0][1]), nullptr);
    EXPECT_EQ(pictures.find(pictures.ids().numbers[0][2]), nullptr);
    std::string warnings;
    for (const std::string& w : pictures.warnings()) warnings += w + "\n";
    EXPECT_NE(warnings.find("NUM_0"), std::string::npos) << warnings;
    EXPECT_NE(warnings.find("2000x1"), std::string::npos) << warnings;
    EXPECT_NE(warnings.find("NUM_2"), std::string::npos) << warnings;
    EXPECT_NE(warnings.find("conchars"), std::string::npos) << warnings;
    EXPECT_GT(pictures.missing().size(), 50u);  // faces, weapons, ...

    // Drawing with most pictures missing: only the bar itself.
    ClientState client;
    enter_level(client);
    ASSERT_FALSE(client.apply(player_data(100, 100, 10, kItemShotgun | kItemShells)));
    std::vector<EmittedQuad> quads = hud_quads(client, hud_frame(kW, kH, 100), pictures);
    ASSERT_EQ(quads.size(), 1u);
    EXPECT_TRUE(drawn_at(quads, pictures, pictures.ids().sbar, 0, kBarRow));
}

TEST(HudPicturesLoading, NoPicturesDrawNothing) {
    HudPictures none;
    ClientState client;
    enter_level(client);
    HudFrame frame = hud_frame(kW, kH, 100);
    frame.settings.crosshair = true;
    EXPECT_FALSE(hud_has_content(client, frame, none));
    EXPECT_TRUE(hud_quads(client, frame, none).empty());
}

// ------------------------------------------------------------------ numbers

std::string characters(int64_t value, int digits) {
    std::array<char, 24> out{};
    size_t n = big_number_characters(value, digits, out);
    return std::string(out.data(), n);
}

TEST(BigNumbers, RightAlignedFieldKeepsTheLastCharacters) {
    EXPECT_EQ(characters(100, 3), "100");
    EXPECT_EQ(characters(7, 3), "7");
    EXPECT_EQ(characters(-5, 3), "-5");
    EXPECT_EQ(characters(-100, 3), "100");
    EXPECT_EQ(characters(1234, 3), "234");
    EXPECT_EQ(characters(0, 3), "0");
    EXPECT_EQ(characters(INT64_MIN, 3), "808");
    EXPECT_EQ(characters(42, 0), "");
    EXPECT_EQ(characters(42, -3), "");
}

// ------------------------------------------------------------------ the status bar

TEST_F(HudLayout, StatusBarNumbersFaceAndIconsAtQuakesPlaces) {
    ClientState client;
    enter_level(client);
    ASSERT_FALSE(client.apply(player_data(57, 200, 8, kItemShells | kItemArmor2 | kItemShotgun)));
    std::vector<EmittedQuad> quads = hud_quads(client, hud_frame(kW, kH, 110), pictures());
    const auto& white = ids().numbers[kWhiteNumbers];
    const auto& red = ids().numbers[kRedNumbers];
    EXPECT_TRUE(drawn_at(quads, pictures(), ids().sbar, 0, kBarRow));
    // Armour "200" in the field from x 24; health " 57" from 136 (right-aligned); ammo "  8"
    // from 248, red (10 or less).
    EXPECT_TRUE(drawn_at(quads, pictures(), white[2], 24, kBarRow));
    EXPECT_EQ(quads_of(quads, pictures(), white[0]).size(), 2u);
    EXPECT_TRUE(drawn_at(quads, pictures(), white[0], 48, kBarRow));
    EXPECT_TRUE(drawn_at(quads, pictures(), white[0], 72, kBarRow));
    EXPECT_TRUE(drawn_at(quads, pictures(), white[5], 160, kBarRow));
    EXPECT_TRUE(drawn_at(quads, pictures(), white[7], 184, kBarRow));
    EXPECT_TRUE(drawn_at(quads, pictures(), red[8], 296, kBarRow));
    EXPECT_TRUE(quads_of(quads, pictures(), white[8]).empty());
    // 57 / 20 = 2: the third face of five (face3), no pain.
    EXPECT_TRUE(drawn_at(quads, pictures(), ids().faces[2][0], 112, kBarRow));
    EXPECT_TRUE(drawn_at(quads, pictures(), ids().armor[1], 0, kBarRow));
    EXPECT_TRUE(drawn_at(quads, pictures(), ids().ammo[0], 224, kBarRow));
    // viewsize 110: no inventory.
    EXPECT_TRUE(quads_of(quads, pictures(), ids().ibar).empty());
}

TEST_F(HudLayout, LowValuesTurnRedAndInvulnerabilityShows666) {
    ClientState client;
    enter_level(client);
    ASSERT_FALSE(client.apply(player_data(25, 26, 11, kItemInvulnerability)));
    std::vector<EmittedQuad> quads = hud_quads(client, hud_frame(kW, kH, 110), pictures());
    const auto& red = ids().numbers[kRedNumbers];
    EXPECT_TRUE(drawn_at(quads, pictures(), red[6], 24, kBarRow));  // 666, armour's field
    EXPECT_TRUE(drawn_at(quads, pictures(), red[6], 72, kBarRow));
    EXPECT_TRUE(drawn_at(quads, pictures(), ids().disc, 0, kBarRow));
    EXPECT_TRUE(drawn_at(quads, pictures(), red[2], 160, kBarRow));  // health 25: red
    EXPECT_TRUE(drawn_at(quads, pictures(), red[5], 184, kBarRow));
    EXPECT_TRUE(drawn_at(quads, pictures(), ids().numbers[0][1], 272, kBarRow));  // ammo 11
    EXPECT_TRUE(drawn_at(quads, pictures(), ids().face_invulnerable, 112, kBarRow));
}

TEST_F(HudLayout, ViewsizeDecidesWhichBarsShow) {
    ClientState client;
    enter_level(client);
    ASSERT_FALSE(client.apply(player_data(100, 0, 20, kItemShotgun | kItemShells)));
    for (float scale : {1.0f, 2.0f}) {
        SCOPED_TRACE("scale " + std::to_string(scale));
        int w = static_cast<int>(kW * scale), h = static_cast<int>(kH * scale);
        EXPECT_TRUE(hud_quads(client, hud_frame(w, h, 120, scale), pictures()).empty());
        auto lowest_top = [](const std::vector<EmittedQuad>& quads) {
            float top = 1e9f;
            for (const EmittedQuad& q : quads) top = std::min(top, q.y0);
            return top;
        };
        std::vector<EmittedQuad> bar = hud_quads(client, hud_frame(w, h, 110, scale), pictures());
        ASSERT_FALSE(bar.empty());
        EXPECT_EQ(lowest_top(bar), h - 24 * scale);
        std::vector<EmittedQuad> both = hud_quads(client, hud_frame(w, h, 100, scale), pictures());
        EXPECT_EQ(lowest_top(both), h - 48 * scale);
        EXPECT_TRUE(drawn_at(both, pictures(), ids().ibar, 0, h - 48 * scale, scale));
        EXPECT_TRUE(drawn_at(both, pictures(), ids().sbar, 0, h - 24 * scale, scale));
        // Below 100 Quake shrinks the view; here the bars stay as at 100.
        EXPECT_EQ(hud_quads(client, hud_frame(w, h, 30, scale), pictures()).size(), both.size());
    }
}

TEST_F(HudLayout, TheBarIsCentredAndScaledToWhatFits) {
    ClientState client;
    enter_level(client);
    ASSERT_FALSE(client.apply(player_data(100, 0, 20, 0)));
    // 640 wide at scr_sbarscale 1.6: 512 pixels from x 64, 38.4 rows tall.
    auto quads = hud_quads(client, hud_frame(640, 480, 110, 1.6f), pictures());
    EXPECT_TRUE(
        drawn_at(quads, pictures(), ids().sbar, 64, std::floor(480 - 48 * 1.6f) + 24 * 1.6f, 1.6f));
    // scr_sbarscale 3 on a 640-wide screen: limited to 2.
    quads = hud_quads(client, hud_frame(640, 480, 110, 3), pictures());
    EXPECT_TRUE(drawn_at(quads, pictures(), ids().sbar, 0, 480 - 48, 2));
    // A screen narrower than the bar shrinks it rather than cutting it off.
    quads = hud_quads(client, hud_frame(160, 120, 110, 1), pictures());
    EXPECT_TRUE(drawn_at(quads, pictures(), ids().sbar, 0, 120 - 12, 0.5f));
}

// ------------------------------------------------------------------ the inventory

TEST_F(HudLayout, InventoryShowsOwnedWeaponsAmmoCountsItemsAndSigils) {
    ClientState client;
    enter_level(client, 10.0);
    ASSERT_FALSE(client.apply(player_data(100, 0, 25,
                                          kItemShotgun | kItemRocketLauncher | kItemLightning |
                                              kItemKey2 | kItemQuad | (kItemSigil1 << 2),
                                          kItemRocketLauncher)));
    client.set_time(12.0);  // the pickup flashes are over
    std::vector<EmittedQuad> quads = hud_quads(client, hud_frame(kW, kH, 100), pictures());
    const float icons = kInventoryRow + 8;
    EXPECT_TRUE(drawn_at(quads, pictures(), ids().ibar, 0, kInventoryRow));
    EXPECT_TRUE(drawn_at(quads, pictures(), ids().weapons[kWeaponOwned][0], 0, icons));
    EXPECT_TRUE(drawn_at(quads, pictures(), ids().weapons[kWeaponInHand][5], 120, icons));
    EXPECT_TRUE(drawn_at(quads, pictures(), ids().weapons[kWeaponOwned][6], 144, icons));
    EXPECT_TRUE(quads_of(quads, pictures(), ids().weapons[kWeaponOwned][1]).empty());
    EXPECT_TRUE(drawn_at(quads, pictures(), ids().items[1], 192 + 16, icons));  // gold key
    EXPECT_TRUE(drawn_at(quads, pictures(), ids().items[5], 192 + 80, icons));  // quad
    EXPECT_TRUE(drawn_at(quads, pictures(), ids().sigils[2], 288 + 16, icons));
    EXPECT_EQ(quads_of(quads, pictures(), ids().sigils[0]).size(), 0u);
    // 25 shells in the small digits (conchars 18 + digit) at x (6 * 0 + 2) * 8 + 2 and
    // (6 * 0 + 3) * 8 + 2; no leading blank drawn.
    std::vector<PlacedGlyph> placed = glyphs(quads, pictures());
    EXPECT_TRUE(has_glyph(placed, 18 + 2, 18, kInventoryRow));
    EXPECT_TRUE(has_glyph(placed, 18 + 5, 26, kInventoryRow));
    // Nails, rockets, cells are 0: one "0" each, in their columns' third place.
    EXPECT_TRUE(has_glyph(placed, 18, (6 * 1 + 3) * 8 + 2, kInventoryRow));
    EXPECT_TRUE(has_glyph(placed, 18, (6 * 3 + 3) * 8 + 2, kInventoryRow));
    EXPECT_EQ(placed.size(), 5u);
}

TEST(Inventory, APickedUpWeaponFlashesForOneSecond) {
    ClientState client;
    enter_level(client, 10.0);
    ASSERT_FALSE(client.apply(player_data(100, 0, 0, kItemShotgun, kItemShotgun)));
    client.set_time(20.0);
    ASSERT_FALSE(client.apply(player_data(100, 0, 0, kItemShotgun | kItemNailgun, kItemShotgun)));
    const PlayerState& p = client.player();
    std::vector<int> frames;
    for (double t : {20.0, 20.15, 20.25, 20.35, 20.45, 20.55, 20.95, 21.0, 25.0}) {
        frames.push_back(weapon_frame(p, 2, t));
    }
    EXPECT_EQ(frames, (std::vector<int>{2, 3, 4, 5, 6, 2, 6, kWeaponOwned, kWeaponOwned}));
    EXPECT_EQ(weapon_frame(p, 0, 25.0), kWeaponInHand);
    EXPECT_EQ(weapon_frame(p, 2, 19.0), 2) << "a clock behind the pickup counts as the pickup";
}

// ------------------------------------------------------------------ the face

TEST_F(HudLayout, FaceFollowsHealthPainAndPowerups) {
    ClientState client;
    enter_level(client, 10.0);
    struct Case {
        int health;
        int32_t items;
        PictureId expected;
    };
    for (const Case& c :
         {Case{200, 0, ids().faces[4][0]}, Case{100, 0, ids().faces[4][0]},
          Case{99, 0, ids().faces[4][0]}, Case{80, 0, ids().faces[4][0]},
          Case{79, 0, ids().faces[3][0]}, Case{19, 0, ids().faces[0][0]},
          Case{-40, 0, ids().faces[0][0]}, Case{50, kItemQuad, ids().face_quad},
          Case{50, kItemInvisibility, ids().face_invisible},
          Case{50, kItemInvisibility | kItemInvulnerability, ids().face_invisible_invulnerable},
          Case{50, kItemInvulnerability | kItemQuad, ids().face_quad}}) {
        SCOPED_TRACE("health " + std::to_string(c.health) + " items " + std::to_string(c.items));
        ASSERT_FALSE(client.apply(player_data(c.health, 0, 0, c.items)));
        EXPECT_EQ(face_picture(ids(), client), c.expected);
    }
    ASSERT_FALSE(client.apply(player_data(50, 0, 0, 0)));
    svc::Damage hit;
    hit.blood = 10;
    ASSERT_FALSE(client.apply(hit));
    EXPECT_EQ(face_picture(ids(), client), ids().faces[2][1]);
    client.set_time(10.3);
    EXPECT_EQ(face_picture(ids(), client), ids().faces[2][0]);
}

// ------------------------------------------------------------------ scoreboards

TEST_F(HudLayout, DeadPlayersSeeTheScoreboardInsteadOfTheStatusBar) {
    ClientState client;
    enter_level(client);
    ASSERT_FALSE(client.apply(player_data(0, 50, 10, kItemShotgun)));
    ASSERT_FALSE(client.apply(svc::UpdateStat{kStatTotalMonsters, 12}));
    ASSERT_FALSE(client.apply(svc::UpdateStat{kStatMonsters, 3}));
    std::vector<EmittedQuad> quads = hud_quads(client, hud_frame(kW, kH, 120), pictures());
    EXPECT_TRUE(drawn_at(quads, pictures(), ids().scorebar, 0, kBarRow));
    EXPECT_TRUE(quads_of(quads, pictures(), ids().sbar).empty());
    std::vector<PlacedGlyph> placed = glyphs(quads, pictures());
    // "Kills: 3/12" from x 8 on the bar's second text row; the title "The Test Level
    // (test1)" (22 characters) centred on its first.
    EXPECT_TRUE(has_glyph(placed, 'K', 8, kBarRow + 12));
    EXPECT_TRUE(has_glyph(placed, '3', 8 + 7 * 8, kBarRow + 12));
    EXPECT_TRUE(has_glyph(placed, 'T', 160 - 22 * 4, kBarRow + 4));
    EXPECT_TRUE(has_glyph(placed, '1', 160 - 22 * 4 + 20 * 8, kBarRow + 4));
    // "Secrets: 0/0" ends at x 312.
    EXPECT_TRUE(has_glyph(placed, '0', 312 - 8, kBarRow + 12));
}

svc::UpdateName name(int client, std::string text) {
    svc::UpdateName m;
    m.client = client;
    m.name = std::move(text);
    return m;
}
svc::UpdateFrags frags(int client, int value) {
    svc::UpdateFrags m;
    m.client = client;
    m.frags = value;
    return m;
}

TEST(Scoreboard, PlayersByFragsMostFirstNamelessLeftOut) {
    ClientState client;
    enter_level(client, 10.0, 8, kGameTypeDeathmatch);
    for (auto m :
         {ServerMessage{name(0, "a")}, ServerMessage{name(1, "b")}, ServerMessage{name(3, "d")},
          ServerMessage{name(4, "e")}, ServerMessage{frags(0, 5)}, ServerMessage{frags(1, 20)},
          ServerMessage{frags(2, 99)}, ServerMessage{frags(3, -3)}, ServerMessage{frags(4, 20)}}) {
        ASSERT_FALSE(client.apply(m));
    }
    FragOrder order = sort_frags(client);
    ASSERT_EQ(order.count, 4u);
    EXPECT_EQ((std::vector<int>(order.clients.begin(), order.clients.begin() + 4)),
              (std::vector<int>{1, 4, 0, 3}));
}

TEST_F(HudLayout, DeathmatchShowsFragsOnTheInventoryAndTheMiniScoreboard) {
    ClientState client;
    enter_level(client, 10.0, 4, kGameTypeDeathmatch);
    for (auto m : {ServerMessage{name(0, "ranger")}, ServerMessage{name(1, "ogre")},
                   ServerMessage{frags(0, 7)}, ServerMessage{frags(1, 12)},
                   ServerMessage{player_data(100, 0, 0, 0)}}) {
        ASSERT_FALSE(client.apply(m));
    }
    svc::SetView view;
    view.entity = 1;  // the viewer is client 0
    ASSERT_FALSE(client.apply(view));
    // 640 wide at scale 1: the deathmatch bar starts at x 0 and the mini scoreboard fits.
    std::vector<EmittedQuad> quads = hud_quads(client, hud_frame(640, 480, 100), pictures());
    std::vector<PlacedGlyph> placed = glyphs(quads, pictures());
    const float inventory = 480 - 48;
    EXPECT_TRUE(drawn_at(quads, pictures(), ids().sbar, 0, 480 - 24));
    // On the inventory: ogre (12) first at x 184, ranger (7) second at 216, bracketed.
    EXPECT_TRUE(has_glyph(placed, '1', 184 + 12 + 8, inventory));
    EXPECT_TRUE(has_glyph(placed, '7', 216 + 12 + 16, inventory));
    EXPECT_TRUE(has_glyph(placed, 16, 216 + 6, inventory));
    EXPECT_TRUE(has_glyph(placed, 17, 216 + 32, inventory));
    // The mini scoreboard from x 324: names at x 372.
    EXPECT_TRUE(has_glyph(placed, 'o', 372, inventory));
    EXPECT_TRUE(has_glyph(placed, 'r', 372, inventory + 8));
    // Solid fills in the players' colours behind the frags.
    size_t fills = std::count_if(quads.begin(), quads.end(),
                                 [](const EmittedQuad& q) { return q.sampling == kSampleNone; });
    EXPECT_EQ(fills, 8u);
}

// ------------------------------------------------------------------ intermission, crosshair

TEST_F(HudLayout, IntermissionDrawsTheLevelStatsEvenWithoutItsPictures) {
    ClientState client;
    enter_level(client, 75.4);
    ASSERT_FALSE(client.apply(player_data(100, 0, 0, 0)));
    ASSERT_FALSE(client.apply(svc::UpdateStat{kStatSecrets, 2}));
    ASSERT_FALSE(client.apply(svc::UpdateStat{kStatTotalSecrets, 5}));
    ASSERT_FALSE(client.apply(svc::Intermission{}));
    // The menu canvas is 320 x 200 centred: at 400 x 300 its origin is (40, 50).
    std::vector<EmittedQuad> quads = hud_quads(client, hud_frame(400, 300), pictures());
    const auto& white = ids().numbers[kWhiteNumbers];
    // 75 s: "1" minute right-aligned from 152, ':' at 224, "1" "5" at 240 and 264.
    EXPECT_TRUE(drawn_at(quads, pictures(), white[1], 40 + 152 + 48, 50 + 64));
    EXPECT_TRUE(drawn_at(quads, pictures(), ids().colon, 40 + 224, 50 + 64));
    EXPECT_TRUE(drawn_at(quads, pictures(), white[1], 40 + 240, 50 + 64));
    EXPECT_TRUE(drawn_at(quads, pictures(), white[5], 40 + 264, 50 + 64));
    // Secrets 2 / 5.
    EXPECT_TRUE(drawn_at(quads, pictures(), white[2], 40 + 152 + 48, 50 + 104));
    EXPECT_TRUE(drawn_at(quads, pictures(), ids().slash, 40 + 224, 50 + 104));
    EXPECT_TRUE(drawn_at(quads, pictures(), white[5], 40 + 240 + 48, 50 + 104));
    // No status bar at the intermission.
    EXPECT_TRUE(quads_of(quads, pictures(), ids().sbar).empty());
}

TEST_F(HudLayout, CrosshairIsAPlusAtTheCentre) {
    ClientState client;
    enter_level(client);
    ASSERT_FALSE(client.apply(player_data(100, 0, 0, 0)));
    HudFrame frame = hud_frame(640, 480, 120);
    EXPECT_TRUE(hud_quads(client, frame, pictures()).empty());
    frame.settings.crosshair = true;
    std::vector<PlacedGlyph> placed = glyphs(hud_quads(client, frame, pictures()), pictures());
    EXPECT_EQ(placed, (std::vector<PlacedGlyph>{{'+', 316, 236}}));
}

// ------------------------------------------------------------------ untrusted values

TEST_F(HudLayout, AbsurdStatsAndTimesDrawWithoutTrouble) {
    for (int value : {INT_MIN, -1000000, -1, 0, 1000000, INT_MAX}) {
        SCOPED_TRACE(value);
        ClientState client;
        enter_level(client, 1.0e300, 16, kGameTypeDeathmatch);
        svc::ClientData d = player_data(value, value, value, -1, value);
        d.shells = d.nails = d.rockets = d.cells = value;
        ASSERT_FALSE(client.apply(d));
        for (int stat = 0; stat < kMaxStats; ++stat) {
            ASSERT_FALSE(client.apply(svc::UpdateStat{stat, value}));
        }
        for (int c = 0; c < 16; ++c) {
            ASSERT_FALSE(client.apply(name(c, std::string(300, static_cast<char>(0x80 + c)))));
            ASSERT_FALSE(client.apply(frags(c, value)));
        }
        svc::Damage hit;
        hit.armor = value;
        hit.blood = value;
        ASSERT_FALSE(client.apply(hit));
        for (float viewsize : {100.0f, 110.0f, 120.0f}) {
            HudFrame frame = hud_frame(1024, 768, viewsize, 1.6f);
            frame.settings.crosshair = true;
            frame.settings.show_scores = true;
            frame.real_time = -1.0e30;
            EXPECT_FALSE(hud_quads(client, frame, pictures()).empty());
        }
        client.set_time(-5.0);  // a clock before every pickup
        EXPECT_FALSE(hud_quads(client, hud_frame(640, 480), pictures()).empty());
        ASSERT_FALSE(client.apply(svc::Intermission{}));
        EXPECT_FALSE(hud_quads(client, hud_frame(640, 480), pictures()).empty());
        ASSERT_FALSE(client.apply(svc::Finale{}));
        hud_quads(client, hud_frame(640, 480), pictures());  // no finale.lmp: nothing, no crash
    }
}

}  // namespace
}  // namespace nq

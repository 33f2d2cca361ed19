#include "hud/status_bar.h"

#include <algorithm>
#include <array>
#include <cstdio>

#include "hud/big_numbers.h"

namespace nq {
namespace {

constexpr float kInventoryIconTop = 8;  // weapons, items and sigils below the ammo counts

// Columns of the status bar.
constexpr float kArmorIconX = 0;
constexpr float kArmorNumberX = 24;
constexpr float kFaceX = 112;
constexpr float kHealthNumberX = 136;
constexpr float kAmmoIconX = 224;
constexpr float kAmmoNumberX = 248;
constexpr int kNumberDigits = 3;
constexpr int kInvulnerableArmorValue = 666;

// Columns of the inventory.
constexpr float kWeaponSpacing = 24;
constexpr float kItemsX = 192;
constexpr float kItemSpacing = 16;
constexpr float kSigilsX = 288;
constexpr float kSigilSpacing = 8;
constexpr int kFirstItemBit = 17;  // key1 .. quad: bits 17..22
constexpr int kItemIcons = 6;
constexpr int kFirstSigilBit = 28;
constexpr int kSigils = 4;
constexpr int kAmmoKinds = 4;
// Ammo counts: conchars 18..27 are the small digits 0..9; each kind's three digits start one
// character into its 48-pixel column, 2 pixels further right.
constexpr uint8_t kSmallDigitZero = 18;
constexpr float kAmmoColumnCharacters = 6;
constexpr float kAmmoCountNudge = 2;

constexpr int kHealthPerFaceStep = 20;
constexpr int kWeaponFlashFramesPerSecond = 10;

uint8_t number_colour(bool low) {
    return low ? kRedNumbers : kWhiteNumbers;
}

bool has(int32_t items, int32_t bits) {
    return (items & bits) != 0;
}

void draw_armor(const HudCanvas& canvas, const HudPictureIds& ids, const PlayerState& player) {
    if (has(player.items, kItemInvulnerability)) {
        draw_big_number(canvas, kArmorNumberX, kStatusBarTop, kInvulnerableArmorValue,
                        kNumberDigits, kRedNumbers);
        canvas.picture(ids.disc, kArmorIconX, kStatusBarTop);
        return;
    }
    int armor = player.stats[kStatArmor];
    draw_big_number(canvas, kArmorNumberX, kStatusBarTop, std::min(armor, kStatusBarMaxValue),
                    kNumberDigits, number_colour(armor <= kLowArmor));
    PictureId icon = has(player.items, kItemArmor3)   ? ids.armor[2]
                     : has(player.items, kItemArmor2) ? ids.armor[1]
                     : has(player.items, kItemArmor1) ? ids.armor[0]
                                                      : kNoPicture;
    canvas.picture(icon, kArmorIconX, kStatusBarTop);
}

void draw_ammo(const HudCanvas& canvas, const HudPictureIds& ids, const PlayerState& player) {
    PictureId icon = has(player.items, kItemShells)    ? ids.ammo[0]
                     : has(player.items, kItemNails)   ? ids.ammo[1]
                     : has(player.items, kItemRockets) ? ids.ammo[2]
                     : has(player.items, kItemCells)   ? ids.ammo[3]
                                                       : kNoPicture;
    canvas.picture(icon, kAmmoIconX, kStatusBarTop);
    int ammo = player.stats[kStatAmmo];
    draw_big_number(canvas, kAmmoNumberX, kStatusBarTop, std::min(ammo, kStatusBarMaxValue),
                    kNumberDigits, number_colour(ammo <= kLowAmmo));
}

void draw_weapons(const HudCanvas& canvas, const HudPictureIds& ids, const PlayerState& player,
                  double now) {
    for (int weapon = 0; weapon < kWeaponItemCount; ++weapon) {
        if (!has(player.items, int32_t{1} << weapon)) continue;
        canvas.picture(ids.weapons[weapon_frame(player, weapon, now)][weapon],
                       static_cast<float>(weapon) * kWeaponSpacing, kInventoryIconTop);
    }
}

void draw_ammo_counts(const HudCanvas& canvas, const PlayerState& player) {
    for (int kind = 0; kind < kAmmoKinds; ++kind) {
        int count = std::clamp(player.stats[kStatShells + kind], 0, kStatusBarMaxValue);
        std::array<char, 4> text{};  // "%3d" of 0..999
        std::snprintf(text.data(), text.size(), "%3d", count);
        for (int place = 0; place < 3; ++place) {
            char c = text[static_cast<size_t>(place)];
            if (c < '0' || c > '9') continue;
            float x =
                (kAmmoColumnCharacters * static_cast<float>(kind) + static_cast<float>(place + 1)) *
                    kCharacterSize +
                kAmmoCountNudge;
            canvas.character(x, kInventoryTop, static_cast<uint8_t>(kSmallDigitZero + (c - '0')));
        }
    }
}

void draw_items_and_sigils(const HudCanvas& canvas, const HudPictureIds& ids,
                           const PlayerState& player) {
    for (int i = 0; i < kItemIcons; ++i) {
        if (has(player.items, int32_t{1} << (kFirstItemBit + i))) {
            canvas.picture(ids.items[i], kItemsX + static_cast<float>(i) * kItemSpacing,
                           kInventoryIconTop);
        }
    }
    for (int i = 0; i < kSigils; ++i) {
        uint32_t bit = uint32_t{1} << (kFirstSigilBit + i);
        if ((static_cast<uint32_t>(player.items) & bit) != 0) {
            canvas.picture(ids.sigils[i], kSigilsX + static_cast<float>(i) * kSigilSpacing,
                           kInventoryIconTop);
        }
    }
}

}  // namespace

int weapon_frame(const PlayerState& player, int weapon, double now) {
    double since_pickup = std::max(0.0, now - player.item_times[static_cast<size_t>(weapon)]);
    if (since_pickup >= kWeaponFlashSeconds) {
        return player.stats[kStatActiveWeapon] == (int32_t{1} << weapon) ? kWeaponInHand
                                                                         : kWeaponOwned;
    }
    // Ten frames a second through the five flash pictures, twice.
    int tick = static_cast<int>(since_pickup * kWeaponFlashFramesPerSecond);
    return 2 + tick % kWeaponFlashFrames;
}

PictureId face_picture(const HudPictureIds& ids, const ClientState& client) {
    const PlayerState& player = client.player();
    bool invisible = has(player.items, kItemInvisibility);
    bool invulnerable = has(player.items, kItemInvulnerability);
    if (invisible && invulnerable) return ids.face_invisible_invulnerable;
    if (has(player.items, kItemQuad)) return ids.face_quad;
    if (invisible) return ids.face_invisible;
    if (invulnerable) return ids.face_invulnerable;
    int health = player.stats[kStatHealth];
    int step = std::clamp(health / kHealthPerFaceStep, 0, kFaceHealthSteps - 1);
    bool pain = client.flashes().pain_face(client.time());
    return ids.faces[static_cast<size_t>(step)][pain ? 1 : 0];
}

void draw_status_bar(const HudCanvas& canvas, const ClientState& client, uint8_t bar_alpha) {
    const HudPictureIds& ids = canvas.pictures().ids();
    const PlayerState& player = client.player();
    canvas.picture(ids.sbar, 0, kStatusBarTop, bar_alpha);
    draw_armor(canvas, ids, player);
    canvas.picture(face_picture(ids, client), kFaceX, kStatusBarTop);
    int health = player.stats[kStatHealth];
    draw_big_number(canvas, kHealthNumberX, kStatusBarTop, std::min(health, kStatusBarMaxValue),
                    kNumberDigits, number_colour(health <= kLowHealth));
    draw_ammo(canvas, ids, player);
}

void draw_inventory(const HudCanvas& canvas, const ClientState& client, uint8_t bar_alpha) {
    const HudPictureIds& ids = canvas.pictures().ids();
    const PlayerState& player = client.player();
    canvas.picture(ids.ibar, 0, kInventoryTop, bar_alpha);
    draw_weapons(canvas, ids, player, client.time());
    draw_ammo_counts(canvas, player);
    draw_items_and_sigils(canvas, ids, player);
}

}  // namespace nq

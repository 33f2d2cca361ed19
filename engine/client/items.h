// The bits of the player's items word (svc_clientdata, PlayerState::items), as Quake's progs
// set them: weapons, ammo kinds, armour, keys, powerups and the episode sigils.
#pragma once

#include <cstdint>

namespace nq {

inline constexpr int32_t kItemShotgun = 1 << 0;
inline constexpr int32_t kItemSuperShotgun = 1 << 1;
inline constexpr int32_t kItemNailgun = 1 << 2;
inline constexpr int32_t kItemSuperNailgun = 1 << 3;
inline constexpr int32_t kItemGrenadeLauncher = 1 << 4;
inline constexpr int32_t kItemRocketLauncher = 1 << 5;
inline constexpr int32_t kItemLightning = 1 << 6;
inline constexpr int32_t kItemShells = 1 << 8;
inline constexpr int32_t kItemNails = 1 << 9;
inline constexpr int32_t kItemRockets = 1 << 10;
inline constexpr int32_t kItemCells = 1 << 11;
inline constexpr int32_t kItemArmor1 = 1 << 13;  // green
inline constexpr int32_t kItemArmor2 = 1 << 14;  // yellow
inline constexpr int32_t kItemArmor3 = 1 << 15;  // red
inline constexpr int32_t kItemKey1 = 1 << 17;    // silver
inline constexpr int32_t kItemKey2 = 1 << 18;    // gold
inline constexpr int32_t kItemInvisibility = 1 << 19;
inline constexpr int32_t kItemInvulnerability = 1 << 20;
inline constexpr int32_t kItemSuit = 1 << 21;
inline constexpr int32_t kItemQuad = 1 << 22;
inline constexpr int32_t kItemSigil1 = 1 << 28;  // bits 28..31: the four sigils

inline constexpr int kWeaponItemCount = 7;  // shotgun .. lightning gun, bits 0..6
inline constexpr int kItemBits = 32;

}  // namespace nq

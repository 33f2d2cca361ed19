// The status bar and the inventory bar above it, as GLQuake and QuakeSpasm draw them, on the
// status bar canvas (hud_canvas.h: 320 x 48 virtual pixels, the inventory in rows 0..23 and
// the status bar in rows 24..47):
//
//   status bar (sbar)  armour icon | armour | face | health | ammo icon | ammo
//                      x 0           24       112    136      224         248
//   inventory (ibar)   ammo counts in small digits along the top row; weapons from x 0, 24
//                      pixels apart (the lightning gun 48), flashing for a second after a
//                      pickup; keys and powerups from x 192, 16 apart; sigils from x 288
//
// Numbers turn red when low (armour and health 25 or less, ammo 10 or less). The face shows
// the health in five steps, a pain frame for 0.2 s after each hit, or the powerup held.
#pragma once

#include <cstdint>

#include "client/client_state.h"
#include "hud/hud_canvas.h"

namespace nq {

inline constexpr int kLowArmor = 25;
inline constexpr int kLowHealth = 25;
inline constexpr int kLowAmmo = 10;
inline constexpr double kWeaponFlashSeconds = 1.0;

// The bar pictures (sbar, ibar, scorebar) are drawn with `bar_alpha`; what lies on them is
// opaque.
void draw_status_bar(const HudCanvas& canvas, const ClientState& client, uint8_t bar_alpha);
void draw_inventory(const HudCanvas& canvas, const ClientState& client, uint8_t bar_alpha);

// Which weapon picture the inventory shows for weapon `weapon` (0..6) at client time `now`:
// kWeaponOwned, kWeaponInHand, or 2..6 for the flash frames after a pickup.
int weapon_frame(const PlayerState& player, int weapon, double now);
// Which face picture the status bar shows (faces[step][pain], or a powerup face).
PictureId face_picture(const HudPictureIds& ids, const ClientState& client);

}  // namespace nq

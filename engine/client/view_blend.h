// The colour the whole view is tinted with this frame (GLQuake's v_blend, drawn by the engine
// as one blended full-screen quad): Quake's four colour shifts mixed in order --
//   contents  the eye in water (brown), slime (green) or lava (orange);
//   damage    the red flash of svc_damage, decaying (screen_flashes.h);
//   bonus     the gold flash of an item pickup, decaying;
//   powerup   quad (blue), else the suit (green), else the ring (grey), else the pentagram
//             (yellow), while the item is held.
// During an intermission only the contents shift applies.
#pragma once

#include <cstdint>
#include <span>

#include "client/client_state.h"
#include "client/screen_flashes.h"

namespace nq {

// Straight-alpha RGBA, 0..1 each; a = 0 means "draw nothing".
struct ScreenBlend {
    float r = 0, g = 0, b = 0, a = 0;
};

// The shift for the view leaf's contents (kContents* of view.h; anything else: none).
ColourShift contents_shift(int contents);
// The shift of the strongest powerup in `items` (none without one).
ColourShift powerup_shift(int32_t items);
// Quake's V_CalcBlend: each shift with percent > 0 is laid over the ones before it; the
// result's alpha is clamped to 0..1.
ScreenBlend mix_colour_shifts(std::span<const ColourShift> shifts);

// The blend for the client's current time, items and intermission, with the eye in
// `eye_contents`.
ScreenBlend view_blend(const ClientState& client, int eye_contents);

}  // namespace nq

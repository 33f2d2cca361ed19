// The menu as quads (no GL: the engine hands the batch to the HUD's drawer), laid out on
// Quake's 320x200 menu canvas (hud_canvas.h, scaled by scr_menuscale) as Quake's menus are:
//   a darkened screen; the plaque (qplaque) at (16, 4) and the screen's title picture centred
//   at y 4; picture menus (Main, Single Player) show their item picture at (72, 32) with the
//   spinning dot cursor 20 lines apart; text menus list rows 8 lines apart from y 32 with the
//   blinking cursor character; Options labels end at x 192, values and sliders start at 220.
// Where the game data lacks a picture, the console font draws the same words in its place.
#pragma once

#include "draw2d/quad_batch.h"
#include "hud/hud_canvas.h"
#include "hud/hud_pictures.h"
#include "menu/menu.h"

namespace nq {

inline constexpr float kMenuRowsTop = 32;           // first row's top, virtual pixels
inline constexpr float kPictureMenuRowHeight = 20;  // Main, Single Player
inline constexpr float kTextMenuRowHeight = 8;      // the rest
inline constexpr float kMenuFadeAlpha = 0.5f;       // Quake's faded screen behind the menu

void build_menu(const Menu& menu, const HudPictures& pictures, const HudScreen& screen,
                double real_time, QuadBatch& batch);

// The row of the menu's current screen under screen pixel (x, y), or -1.
int menu_row_at(const Menu& menu, const HudScreen& screen, float x, float y);

}  // namespace nq

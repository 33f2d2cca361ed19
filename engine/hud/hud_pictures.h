// Every picture the status bar, the inventory, the scoreboards, the intermission screen and the
// menu draw, loaded once from the game data into one atlas: gfx.wad's status-bar pictures and
// conchars, the intermission pictures gfx/complete.lmp, inter.lmp, finale.lmp and ranking.lmp,
// and the menu's gfx/*.lmp (menu/menu_drawing.h).
//
// Loading never fails. A picture the data lacks (LibreQuake has no gfx/complete.lmp), or one
// that does not decode or is absurdly large, gets kNoPicture and its name in missing() or
// warnings(); the overlays skip what is missing and draw the rest.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "client/items.h"
#include "draw2d/picture_atlas.h"
#include "draw2d/rgba_image.h"
#include "formats/palette.h"
#include "formats/wad.h"

namespace nq {

class Vfs;

using PictureId = uint16_t;  // index into HudPictures' atlas
inline constexpr PictureId kNoPicture = 0xffff;

inline constexpr int kWhiteNumbers = 0;       // num_*: the status bar's big digits
inline constexpr int kRedNumbers = 1;         // anum_*: the same, red, for low values
inline constexpr int kMinusDigit = 10;        // numbers[colour][10] is the minus sign
inline constexpr int kWeaponOwned = 0;        // weapons[0]: inv_*, owned
inline constexpr int kWeaponInHand = 1;       // weapons[1]: inv2_*, the one in use
inline constexpr int kWeaponFlashFrames = 5;  // weapons[2..6]: inva1_* .. inva5_*, picked up
inline constexpr int kFaceHealthSteps = 5;    // faces[0] face5 (near death) .. [4] face1

inline constexpr int kMenuDotFrames = 6;  // menudot1..6, the main menu's spinning cursor
inline constexpr int kMaxHelpPages = 6;   // help0..help5

// The menu's pictures (gfx/*.lmp): Quake's plaque, titles and item lists.
struct MenuPictureIds {
    PictureId plaque = kNoPicture;               // qplaque, left of every menu
    PictureId main_title = kNoPicture;           // ttl_main
    PictureId main_items = kNoPicture;           // mainmenu
    PictureId single_player_title = kNoPicture;  // ttl_sgl
    PictureId single_player_items = kNoPicture;  // sp_menu
    PictureId options_title = kNoPicture, load_title = kNoPicture, save_title = kNoPicture;
    std::array<PictureId, kMenuDotFrames> dots{};
    std::array<PictureId, kMaxHelpPages> help{};
};

// The ids of the pictures, by what they show. (In a HudPictures that loaded nothing, every id
// resolves to no picture.)
struct HudPictureIds {
    PictureId sbar = kNoPicture, ibar = kNoPicture, scorebar = kNoPicture;
    PictureId disc = kNoPicture;  // the armour icon while invulnerable
    std::array<std::array<PictureId, 11>, 2> numbers{};
    PictureId colon = kNoPicture, slash = kNoPicture;
    std::array<std::array<PictureId, kWeaponItemCount>, 2 + kWeaponFlashFrames> weapons{};
    std::array<PictureId, 4> ammo{};    // shells, nails, rockets, cells
    std::array<PictureId, 3> armor{};   // green, yellow, red
    std::array<PictureId, 6> items{};   // key1, key2, invisibility, invulnerability, suit, quad
    std::array<PictureId, 4> sigils{};  // the four runes
    std::array<std::array<PictureId, 2>, kFaceHealthSteps> faces{};  // [health / 20][pain]
    PictureId face_invisible = kNoPicture, face_invulnerable = kNoPicture;
    PictureId face_invisible_invulnerable = kNoPicture, face_quad = kNoPicture;
    PictureId conchars = kNoPicture;                      // the 8x8 font, a 16x16 glyph sheet
    PictureId complete = kNoPicture, inter = kNoPicture;  // single-player intermission
    PictureId finale = kNoPicture, ranking = kNoPicture;  // episode end, deathmatch scores
    MenuPictureIds menu;
};

// Pictures larger than this on either side are no Quake HUD picture (the largest, inter.lmp,
// is 160x144): they are refused rather than packed.
inline constexpr int kMaxHudPictureSide = 1024;

class HudPictures {
  public:
    HudPictures() = default;  // no pictures: nothing is drawn
    // `vfs` (may be null) provides gfx/*.lmp.
    static HudPictures load(const Wad& gfx_wad, const Palette& palette, const Vfs* vfs);

    const HudPictureIds& ids() const { return ids_; }
    // The picture's place in the atlas, or nullptr when the data lacks it.
    const AtlasPicture* find(PictureId id) const;
    const RgbaImage& atlas_image() const { return atlas_.image; }
    bool empty() const { return atlas_.image.empty(); }
    // A palette colour, for Quake's solid fills (the player colours of the scoreboards).
    Rgb palette_colour(uint8_t index) const { return palette_.colors[index]; }

    const std::vector<std::string>& missing() const { return missing_; }
    const std::vector<std::string>& warnings() const { return warnings_; }

  private:
    HudPictureIds ids_;
    PictureAtlas atlas_;
    Palette palette_;
    std::vector<std::string> missing_;
    std::vector<std::string> warnings_;
};

}  // namespace nq

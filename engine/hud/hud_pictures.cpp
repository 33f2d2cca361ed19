#include "hud/hud_pictures.h"

#include <string_view>
#include <utility>

#include "console/console_font.h"
#include "formats/lmp.h"
#include "fs/vfs.h"

namespace nq {
namespace {

constexpr std::array<const char*, kWeaponItemCount> kWeaponNames = {
    "shotgun", "sshotgun", "nailgun", "snailgun", "rlaunch", "srlaunch", "lightng"};

// Collects the decoded pictures in load order; the index of each is its PictureId.
class PictureCollector {
  public:
    PictureCollector(const Wad& wad, const Palette& palette, const Vfs* vfs,
                     std::vector<std::string>& missing, std::vector<std::string>& warnings)
        : wad_(wad), palette_(palette), vfs_(vfs), missing_(missing), warnings_(warnings) {}

    // A qpic lump of gfx.wad.
    PictureId from_wad(const std::string& name) {
        const WadLump* lump = wad_.find(name);
        if (!lump) return absent(name);
        Result<Pic> pic = parse_wad_pic(wad_, *lump);
        if (!pic) return broken(pic.error().to_string());
        return add(name, *pic);
    }

    // A loose or packed gfx/*.lmp file.
    PictureId from_file(const std::string& path) {
        if (!vfs_ || !vfs_->exists(path)) return absent(path);
        auto bytes = vfs_->read(path);
        if (!bytes) return broken(bytes.error().to_string());
        Result<Pic> pic = parse_qpic(*bytes, path);
        if (!pic) return broken(pic.error().to_string());
        return add(path, *pic);
    }

    // The console font, whose transparent index is 0 rather than 255.
    PictureId conchars() {
        Result<RgbaImage> font = load_conchars_font(wad_, palette_);
        if (!font) return broken(font.error().to_string());
        return push(std::move(*font));
    }

    std::vector<RgbaImage> take_images() { return std::move(images_); }

  private:
    PictureId absent(const std::string& name) {
        missing_.push_back(name);
        return kNoPicture;
    }
    PictureId broken(std::string why) {
        warnings_.push_back(std::move(why));
        return kNoPicture;
    }
    PictureId add(const std::string& name, const Pic& pic) {
        if (pic.width > kMaxHudPictureSide || pic.height > kMaxHudPictureSide) {
            return broken(name + " is " + std::to_string(pic.width) + "x" +
                          std::to_string(pic.height) + ", too large for a status bar picture");
        }
        return push(pic_to_rgba(pic, palette_));
    }
    PictureId push(RgbaImage image) {
        images_.push_back(std::move(image));
        return static_cast<PictureId>(images_.size() - 1);
    }

    const Wad& wad_;
    const Palette& palette_;
    const Vfs* vfs_;
    std::vector<std::string>& missing_;
    std::vector<std::string>& warnings_;
    std::vector<RgbaImage> images_;
};

void collect_menu(PictureCollector& c, MenuPictureIds& ids) {
    ids.plaque = c.from_file("gfx/qplaque.lmp");
    ids.main_title = c.from_file("gfx/ttl_main.lmp");
    ids.main_items = c.from_file("gfx/mainmenu.lmp");
    ids.single_player_title = c.from_file("gfx/ttl_sgl.lmp");
    ids.single_player_items = c.from_file("gfx/sp_menu.lmp");
    ids.options_title = c.from_file("gfx/p_option.lmp");
    ids.load_title = c.from_file("gfx/p_load.lmp");
    ids.save_title = c.from_file("gfx/p_save.lmp");
    for (int frame = 0; frame < kMenuDotFrames; ++frame) {
        ids.dots[size_t(frame)] = c.from_file("gfx/menudot" + std::to_string(frame + 1) + ".lmp");
    }
    for (int page = 0; page < kMaxHelpPages; ++page) {
        ids.help[size_t(page)] = c.from_file("gfx/help" + std::to_string(page) + ".lmp");
    }
}

// Quake's picture names for each slot of HudPictureIds.
void collect(PictureCollector& c, HudPictureIds& ids) {
    ids.sbar = c.from_wad("sbar");
    ids.ibar = c.from_wad("ibar");
    ids.scorebar = c.from_wad("scorebar");
    ids.disc = c.from_wad("disc");
    for (int digit = 0; digit < 10; ++digit) {
        ids.numbers[kWhiteNumbers][digit] = c.from_wad("num_" + std::to_string(digit));
        ids.numbers[kRedNumbers][digit] = c.from_wad("anum_" + std::to_string(digit));
    }
    ids.numbers[kWhiteNumbers][kMinusDigit] = c.from_wad("num_minus");
    ids.numbers[kRedNumbers][kMinusDigit] = c.from_wad("anum_minus");
    ids.colon = c.from_wad("num_colon");
    ids.slash = c.from_wad("num_slash");

    for (int weapon = 0; weapon < kWeaponItemCount; ++weapon) {
        std::string name = kWeaponNames[static_cast<size_t>(weapon)];
        ids.weapons[kWeaponOwned][weapon] = c.from_wad("inv_" + name);
        ids.weapons[kWeaponInHand][weapon] = c.from_wad("inv2_" + name);
        for (int flash = 0; flash < kWeaponFlashFrames; ++flash) {
            ids.weapons[2 + flash][weapon] =
                c.from_wad("inva" + std::to_string(flash + 1) + "_" + name);
        }
    }
    ids.ammo = {c.from_wad("sb_shells"), c.from_wad("sb_nails"), c.from_wad("sb_rocket"),
                c.from_wad("sb_cells")};
    ids.armor = {c.from_wad("sb_armor1"), c.from_wad("sb_armor2"), c.from_wad("sb_armor3")};
    ids.items = {c.from_wad("sb_key1"),   c.from_wad("sb_key2"), c.from_wad("sb_invis"),
                 c.from_wad("sb_invuln"), c.from_wad("sb_suit"), c.from_wad("sb_quad")};
    for (int sigil = 0; sigil < 4; ++sigil) {
        ids.sigils[sigil] = c.from_wad("sb_sigil" + std::to_string(sigil + 1));
    }
    // faces[0] is the face nearest death (face5), faces[4] the healthy one (face1).
    for (int step = 0; step < kFaceHealthSteps; ++step) {
        std::string number = std::to_string(kFaceHealthSteps - step);
        ids.faces[step] = {c.from_wad("face" + number), c.from_wad("face_p" + number)};
    }
    ids.face_invisible = c.from_wad("face_invis");
    ids.face_invulnerable = c.from_wad("face_invul2");
    ids.face_invisible_invulnerable = c.from_wad("face_inv2");
    ids.face_quad = c.from_wad("face_quad");
    ids.conchars = c.conchars();
    ids.complete = c.from_file("gfx/complete.lmp");
    ids.inter = c.from_file("gfx/inter.lmp");
    ids.finale = c.from_file("gfx/finale.lmp");
    ids.ranking = c.from_file("gfx/ranking.lmp");
    collect_menu(c, ids.menu);
}

}  // namespace

HudPictures HudPictures::load(const Wad& gfx_wad, const Palette& palette, const Vfs* vfs) {
    HudPictures pictures;
    PictureCollector collector(gfx_wad, palette, vfs, pictures.missing_, pictures.warnings_);
    collect(collector, pictures.ids_);
    std::vector<RgbaImage> images = collector.take_images();
    pictures.atlas_ = pack_pictures(images);
    pictures.palette_.colors = palette.colors;
    return pictures;
}

const AtlasPicture* HudPictures::find(PictureId id) const {
    if (id >= atlas_.pictures.size()) return nullptr;
    const AtlasPicture& picture = atlas_.pictures[id];
    return picture.present() ? &picture : nullptr;
}

}  // namespace nq

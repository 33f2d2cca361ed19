#include "app/shell/overlay.h"

#include "console/console_font.h"
#include "console/console_keys.h"
#include "fs/vfs.h"
#include "menu/menu_drawing.h"

namespace nq {

Overlay::Overlay(HostCore& host, const GameData& data, const Vfs* vfs, int width, int height)
    : host_(host) {
    console_ = std::make_unique<Console>(host_);
    console_->set_screen_size(width, height);
    if (auto drawer = ConsoleDrawer::create()) {
        console_drawer_.emplace(std::move(drawer.value()));
        if (data.gfx_wad && data.palette) {
            if (auto font = load_conchars_font(*data.gfx_wad, *data.palette)) {
                console_drawer_->set_font(font.value());
            }
        }
    } else {
        start_messages_.push_back("console: " + drawer.error().message);
    }
    hud_ = std::make_unique<Hud>(host_);
    const Wad* gfx_wad = data.gfx_wad ? &*data.gfx_wad : nullptr;
    const Palette* palette = data.palette ? &*data.palette : nullptr;
    for (std::string& line : hud_->load_pictures(gfx_wad, palette, vfs)) {
        start_messages_.push_back(std::move(line));
    }
}

Overlay::~Overlay() {
    menu_.reset();
    hud_.reset();
    console_drawer_.reset();
}

void Overlay::create_menu(const PluginHost& plugins, const DemoSession& session,
                          std::string save_dir) {
    menu_services_ = std::make_unique<EngineMenuServices>(plugins, session, std::move(save_dir));
    menu_ = std::make_unique<Menu>(host_, *menu_services_);
    int pages = 0;
    if (const HudDrawer* drawer = hud_->drawer()) {
        const MenuPictureIds& ids = drawer->pictures().ids().menu;
        while (pages < kMaxHelpPages && drawer->pictures().find(ids.help[size_t(pages)])) ++pages;
    }
    menu_->set_help_pages(pages);
}

bool Overlay::menu_takes_event(const InputEvent& event, bool session_active,
                               const HudScreen& screen) {
    if (event.type == InputEventType::MouseMotion && menu_->active()) {
        const int row = menu_row_at(*menu_, screen, float(event.x), float(event.y));
        if (row >= 0) menu_->point_at(row);
        return true;
    }
    if (event.type != InputEventType::Key || !event.key) return false;
    const std::string_view key = event.key;
    if (!event.down) return false;  // releases end held actions wherever the press went
    if (key == "ESCAPE" && !event.repeat) {
        if (console_->is_open()) {
            console_->set_open(false);
            if (!session_active && !menu_->active()) menu_->open(MenuScreen::Main);
        } else if (menu_->active()) {
            menu_->key_down(key);
        } else {
            menu_->open(MenuScreen::Main);
        }
        return true;
    }
    if (!menu_->active() || console_->is_open() || key == kConsoleToggleKey) return false;
    menu_->key_down(key);
    return true;
}

void Overlay::draw(double real_time, const HudScreen& screen) {
    hud_->count_frame(real_time);
    if (menu_->active()) {
        hud_->draw_overlay(screen.width, screen.height,
                           [&](QuadBatch& batch, const HudPictures& pictures) {
                               build_menu(*menu_, pictures, screen, real_time, batch);
                           });
    }
    if (console_drawer_) console_drawer_->draw(*console_);
}

}  // namespace nq

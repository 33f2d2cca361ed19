// The menu in the engine: what it asks of the engine (styles, save slots), which keys reach it,
// and drawing it over the game, the demo loop or the showroom.
#include "app/engine_menu.h"

#include "app/engine.h"
#include "common/file_io.h"
#include "console/console_keys.h"
#include "menu/menu_drawing.h"
#include "server/savegame.h"

namespace nq {

namespace {

// The second line of a save file: Quake's 39-character comment, '_' standing for spaces.
std::string save_comment_of(const std::vector<uint8_t>& bytes) {
    const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    const size_t first = text.find('\n');
    if (first == std::string_view::npos) return {};
    const size_t second = text.find('\n', first + 1);
    std::string comment(text.substr(
        first + 1, second == std::string_view::npos ? std::string_view::npos : second - first - 1));
    while (!comment.empty() && (comment.back() == '\r' || comment.back() == ' ')) {
        comment.pop_back();
    }
    for (char& c : comment) {
        if (c == '_') c = ' ';
        if (static_cast<unsigned char>(c) < 32) c = ' ';
    }
    return comment.substr(0, server::kSaveCommentLength);
}

}  // namespace

EngineMenuServices::EngineMenuServices(const PluginHost& plugins, const DemoSession& demo,
                                       std::string save_dir)
    : plugins_(plugins), demo_(demo), save_dir_(std::move(save_dir)) {}

std::vector<std::string> EngineMenuServices::styles() const {
    std::vector<std::string> names;
    // `null` draws nothing (engine tests, CPU timing): not a style a player picks.
    for (const PluginInfo& info : plugins_.available()) {
        if (info.name != "null") names.push_back(info.name);
    }
    return names;
}

std::string EngineMenuServices::active_style() const {
    return plugins_.active_name();
}

std::vector<StyleSetting> EngineMenuServices::style_settings() const {
    const nqr_renderer* table = plugins_.active();
    return table ? read_style_settings(*table).settings : std::vector<StyleSetting>{};
}

std::string EngineMenuServices::save_comment(int slot) const {
    auto bytes = read_file(save_dir_ + "/s" + std::to_string(slot) + ".sav");
    return bytes ? save_comment_of(*bytes) : std::string();
}

bool EngineMenuServices::game_running() const {
    const LiveGame* game = demo_.live();
    return game && game->running();
}

// ---- Engine

void Engine::create_menu() {
    const std::string save_dir = user_dir() + "/" + options_.game.value_or("id1");
    menu_services_ =
        std::make_unique<EngineMenuServices>(frames_->plugins(), sessions_->session(), save_dir);
    menu_ = std::make_unique<Menu>(host_, *menu_services_);
    int pages = 0;
    if (const HudDrawer* drawer = hud_->drawer()) {
        const MenuPictureIds& ids = drawer->pictures().ids().menu;
        while (pages < kMaxHelpPages && drawer->pictures().find(ids.help[size_t(pages)])) ++pages;
    }
    menu_->set_help_pages(pages);
}

// ESCAPE opens the menu (or goes back in it; closes the console first when that is open); every
// other key goes to the open menu, except the console's own key. Returns true when the event
// is the menu's.
bool Engine::menu_takes_event(const InputEvent& event) {
    if (event.type == InputEventType::MouseMotion && menu_->active()) {
        const HudScreen screen = menu_screen();
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
            if (!sessions_->session().active() && !menu_->active()) menu_->open(MenuScreen::Main);
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

HudScreen Engine::menu_screen() const {
    return HudScreen{screen_->width(), screen_->height(), cvars_.menu_scale->value()};
}

void Engine::draw_menu(double real_time) {
    if (!menu_->active()) return;
    const HudScreen screen = menu_screen();
    hud_->draw_overlay(screen.width, screen.height,
                       [&](QuadBatch& batch, const HudPictures& pictures) {
                           build_menu(*menu_, pictures, screen, real_time, batch);
                       });
}

}  // namespace nq

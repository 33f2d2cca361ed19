#include "menu/menu.h"

#include <algorithm>
#include <cmath>

#include "host/number_text.h"

namespace nq {
namespace {

enum class Option {
    Console,
    Defaults,
    ScreenSize,
    Brightness,
    MouseSpeed,
    FieldOfView,
    SoundVolume,
    MusicVolume,
    AlwaysRun,
    InvertMouse,
    MouseLook,
    Obscurance,
    ObscuranceHalf,
    Style,
    StyleSettings,
};

// Options rows; one whose cvar the engine does not have (no sound system: no `volume`) is
// left out. Ranges are Quake's where it has the option.
struct OptionSpec {
    Option id;
    const char* label;
    const char* cvar;  // nullptr: an action, not a setting
    float min, max, step;
};

constexpr OptionSpec kOptions[] = {
    {Option::Console, "Go to console", nullptr, 0, 0, 0},
    {Option::Defaults, "Reset to defaults", nullptr, 0, 0, 0},
    {Option::ScreenSize, "Screen size", "viewsize", 30, 120, 10},
    {Option::Brightness, "Brightness", "gamma", 0.5f, 1, 0.05f},
    {Option::MouseSpeed, "Mouse speed", "sensitivity", 1, 11, 0.5f},
    {Option::FieldOfView, "Field of view", "fov", 60, 130, 5},
    {Option::SoundVolume, "Sound volume", "volume", 0, 1, 0.1f},
    {Option::MusicVolume, "Music volume", "bgmvolume", 0, 1, 0.1f},
    {Option::AlwaysRun, "Always run", "cl_run", 0, 1, 1},
    {Option::InvertMouse, "Invert mouse", "m_pitch", 0, 0, 0},
    {Option::MouseLook, "Mouse look", "freelook", 0, 1, 1},
    {Option::Obscurance, "Obscurance", "vo_enable", 0, 1, 1},
    {Option::ObscuranceHalf, "Obscurance res", "vo_half", 0, 1, 1},
    {Option::Style, "Renderer style", nullptr, 0, 0, 0},
    {Option::StyleSettings, "Style settings...", nullptr, 0, 0, 0},
};

const char* const kMainRows[] = {"Single Player", "Multiplayer", "Options", "Help", "Quit"};
const char* const kSinglePlayerRows[] = {"New Game", "Load", "Save"};

const OptionSpec& option_spec(Option id) {
    return kOptions[static_cast<int>(id)];
}

// `value` moved `direction` steps of `step` within [min, max], on the grid from min (so
// repeated steps never drift).
float stepped(float value, int direction, float min, float max, float step) {
    const float steps = std::round((value - min) / step) + float(direction);
    return std::clamp(min + steps * step, min, max);
}

float slider_position(float value, float min, float max) {
    return std::clamp((value - min) / (max - min), 0.0f, 1.0f);
}

std::string on_off(bool on) {
    return on ? "on" : "off";
}

bool is_up(std::string_view key) {
    return key == "UPARROW" || key == "MWHEELUP" || key == "KP_UPARROW";
}
bool is_down(std::string_view key) {
    return key == "DOWNARROW" || key == "MWHEELDOWN" || key == "KP_DOWNARROW";
}
bool is_enter(std::string_view key) {
    return key == "ENTER" || key == "KP_ENTER" || key == "MOUSE1";
}
bool is_back(std::string_view key) {
    return key == "ESCAPE" || key == "MOUSE2";
}

}  // namespace

Menu::Menu(HostCore& host, MenuServices& services) : host_(host), services_(services) {
    register_commands();
}

Menu::~Menu() {
    for (const std::string& name : added_commands_) host_.commands().remove_command(name);
}

void Menu::register_commands() {
    const auto add = [this](const char* name, auto fn, const char* description) {
        if (host_.commands().add_command(
                name, [fn](const CommandArgs&) { fn(); }, description)) {
            added_commands_.emplace_back(name);
        }
    };
    add(
        "togglemenu", [this] { toggle(); }, "togglemenu: open or close the menu (ESC)");
    add(
        "menu_main", [this] { open(MenuScreen::Main); }, "menu_main: the main menu");
    add(
        "menu_singleplayer", [this] { open(MenuScreen::SinglePlayer); },
        "menu_singleplayer: new game, load, save");
    add(
        "menu_load", [this] { open(MenuScreen::Load); }, "menu_load: load a saved game");
    add(
        "menu_save", [this] { open(MenuScreen::Save); }, "menu_save: save the running game");
    add(
        "menu_options", [this] { open(MenuScreen::Options); },
        "menu_options: mouse, screen, renderer style");
    add(
        "menu_style", [this] { open(MenuScreen::Style); },
        "menu_style: the active renderer style's settings");
    add(
        "menu_quit", [this] { open(MenuScreen::Quit); }, "menu_quit: ask, then quit");
    add(
        "help", [this] { open(MenuScreen::Help); }, "help: the help pages");
    add(
        "menu_multiplayer",
        [this] {
            open(MenuScreen::Main);
            cursor_ = 1;
            notice_ = "No multiplayer in this engine";
        },
        "menu_multiplayer: (not available)");
}

void Menu::open(MenuScreen screen) {
    if (screen == MenuScreen::Save && !services_.game_running()) {
        if (active()) notice_ = "No game is running to save";
        return;
    }
    screen_ = screen;
    cursor_ = 0;
    help_page_ = 0;
    notice_.clear();
    build_rows();
}

void Menu::toggle() {
    if (screen_ == MenuScreen::None) return open(MenuScreen::Main);
    if (screen_ == MenuScreen::Main) return close();
    open(MenuScreen::Main);
}

void Menu::build_rows() {
    rows_.clear();
    option_ids_.clear();
    switch (screen_) {
        case MenuScreen::Main:
            for (const char* label : kMainRows) rows_.push_back({label, {}, {}, true});
            break;
        case MenuScreen::SinglePlayer:
            for (const char* label : kSinglePlayerRows) rows_.push_back({label, {}, {}, true});
            break;
        case MenuScreen::Load:
        case MenuScreen::Save:
            for (int slot = 0; slot < kSaveSlots; ++slot) {
                std::string comment = services_.save_comment(slot);
                const bool empty = comment.empty();
                rows_.push_back({empty ? "--- UNUSED SLOT ---" : std::move(comment),
                                 {},
                                 {},
                                 screen_ == MenuScreen::Save || !empty});
            }
            break;
        case MenuScreen::Options:
            for (const OptionSpec& spec : kOptions) {
                const Cvar* cvar = spec.cvar ? host_.cvars().find(spec.cvar) : nullptr;
                if (spec.cvar && !cvar) continue;
                MenuRow row{spec.label, {}, {}, true};
                switch (spec.id) {
                    case Option::Brightness:  // brighter to the right: lower gamma
                        row.slider = 1 - slider_position(cvar->value(), spec.min, spec.max);
                        break;
                    case Option::AlwaysRun:
                    case Option::MouseLook:
                    case Option::Obscurance:
                        row.value = on_off(cvar->value() != 0);
                        break;
                    case Option::ObscuranceHalf:
                        row.value = cvar->value() != 0 ? "half" : "full";
                        break;
                    case Option::InvertMouse:
                        row.value = on_off(cvar->value() < 0);
                        break;
                    case Option::Style:
                        row.value = services_.active_style();
                        break;
                    default:
                        if (cvar) row.slider = slider_position(cvar->value(), spec.min, spec.max);
                }
                rows_.push_back(std::move(row));
                option_ids_.push_back(static_cast<int>(spec.id));
            }
            break;
        case MenuScreen::Style:
            style_settings_ = services_.style_settings();
            for (const StyleSetting& setting : style_settings_) {
                const Cvar* cvar = host_.cvars().find(setting.cvar);
                const float value = cvar ? cvar->value() : setting.min;
                MenuRow row{setting.label, {}, {}, cvar != nullptr};
                if (setting.kind == StyleSettingKind::Toggle) row.value = on_off(value != 0);
                if (setting.kind == StyleSettingKind::Range) row.value = format_number(value);
                if (setting.kind == StyleSettingKind::Choice) {
                    const int index = std::clamp(int(value), 0, int(setting.choices.size()) - 1);
                    row.value = setting.choices[size_t(index)];
                }
                rows_.push_back(std::move(row));
            }
            if (rows_.empty()) {
                rows_.push_back(
                    {services_.active_style() + " has no settings of its own", {}, {}, false});
            }
            break;
        case MenuScreen::None:
        case MenuScreen::Help:
        case MenuScreen::Quit:
            break;
    }
    cursor_ = std::clamp(cursor_, 0, std::max(int(rows_.size()) - 1, 0));
    if (!rows_.empty() && !rows_[size_t(cursor_)].enabled) move_cursor(1);
}

void Menu::key_down(std::string_view key) {
    if (!active()) return;
    notice_.clear();
    if (screen_ == MenuScreen::Quit) {
        if (key == "y" || key == "Y" || is_enter(key)) run("quit");
        if (key == "n" || key == "N" || is_back(key)) back();
        return;
    }
    if (is_up(key)) return move_cursor(-1);
    if (is_down(key)) return move_cursor(1);
    if (key == "LEFTARROW" || key == "KP_LEFTARROW") return adjust(-1);
    if (key == "RIGHTARROW" || key == "KP_RIGHTARROW") return adjust(1);
    if (is_enter(key)) return activate();
    if (is_back(key)) return back();
}

void Menu::point_at(int row) {
    if (row >= 0 && row < int(rows_.size()) && rows_[size_t(row)].enabled) cursor_ = row;
}

void Menu::move_cursor(int step) {
    const int count = int(rows_.size());
    for (int tries = 0; tries < count; ++tries) {
        cursor_ = (cursor_ + step + count) % count;
        if (rows_[size_t(cursor_)].enabled) return;
    }
}

void Menu::back() {
    switch (screen_) {
        case MenuScreen::Main:
            return close();
        case MenuScreen::Load:
        case MenuScreen::Save:
            return open(MenuScreen::SinglePlayer);
        case MenuScreen::Style:
            return open(MenuScreen::Options);
        default:
            return open(MenuScreen::Main);
    }
}

void Menu::activate() {
    const bool row_ok =
        cursor_ >= 0 && cursor_ < int(rows_.size()) && rows_[size_t(cursor_)].enabled;
    switch (screen_) {
        case MenuScreen::Main: {
            const MenuScreen next[] = {MenuScreen::SinglePlayer, MenuScreen::None,
                                       MenuScreen::Options, MenuScreen::Help, MenuScreen::Quit};
            if (cursor_ == 1) {
                notice_ = "No multiplayer in this engine";
                return;
            }
            return open(next[cursor_]);
        }
        case MenuScreen::SinglePlayer:
            if (cursor_ == 0) {
                close();
                return run("deathmatch 0; coop 0; map start");
            }
            if (cursor_ == 1) return open(MenuScreen::Load);
            if (!services_.game_running()) {
                notice_ = "No game is running to save";
                return;
            }
            return open(MenuScreen::Save);
        case MenuScreen::Load:
        case MenuScreen::Save: {
            if (!row_ok) return;
            const std::string command =
                (screen_ == MenuScreen::Load ? "load s" : "save s") + std::to_string(cursor_);
            close();
            return run(command);
        }
        case MenuScreen::Options:
            switch (static_cast<Option>(option_ids_[size_t(cursor_)])) {
                case Option::Console:
                    close();
                    return run("toggleconsole");
                case Option::Defaults:
                    run("exec default.cfg");
                    notice_ = "Defaults restored (default.cfg)";
                    return;
                case Option::StyleSettings:
                    return open(MenuScreen::Style);
                default:
                    return adjust(1);
            }
        case MenuScreen::Style:
            if (row_ok) adjust(1);
            return;
        case MenuScreen::Help:
            return adjust(1);
        default:
            return;
    }
}

void Menu::adjust(int direction) {
    if (screen_ == MenuScreen::Options && !option_ids_.empty()) adjust_option(direction);
    if (screen_ == MenuScreen::Style) adjust_style_setting(direction);
    if (screen_ == MenuScreen::Help && help_pages_ > 0) {
        help_page_ = (help_page_ + direction + help_pages_) % help_pages_;
    }
}

void Menu::adjust_option(int direction) {
    const OptionSpec& spec = option_spec(static_cast<Option>(option_ids_[size_t(cursor_)]));
    Cvar* cvar = spec.cvar ? host_.cvars().find(spec.cvar) : nullptr;
    switch (spec.id) {
        case Option::Style:
            return cycle_style(direction);
        case Option::Console:
        case Option::Defaults:
        case Option::StyleSettings:
            return;
        case Option::Brightness:  // right is brighter: gamma goes down
            host_.cvars().set(
                *cvar,
                format_number(stepped(cvar->value(), -direction, spec.min, spec.max, spec.step)),
                CvarSource::kUser);
            break;
        case Option::AlwaysRun:
        case Option::MouseLook:
        case Option::Obscurance:
        case Option::ObscuranceHalf:
            host_.cvars().set(*cvar, cvar->value() != 0 ? "0" : "1", CvarSource::kUser);
            break;
        case Option::InvertMouse:
            host_.cvars().set(*cvar, format_number(-cvar->value()), CvarSource::kUser);
            break;
        default:
            host_.cvars().set(
                *cvar,
                format_number(stepped(cvar->value(), direction, spec.min, spec.max, spec.step)),
                CvarSource::kUser);
    }
    build_rows();
}

void Menu::adjust_style_setting(int direction) {
    if (cursor_ >= int(style_settings_.size())) return;
    const StyleSetting& setting = style_settings_[size_t(cursor_)];
    Cvar* cvar = host_.cvars().find(setting.cvar);
    if (!cvar) return;
    float value = cvar->value();
    switch (setting.kind) {
        case StyleSettingKind::Toggle:
            value = value != 0 ? 0 : 1;
            break;
        case StyleSettingKind::Range:
            value = stepped(value, direction, setting.min, setting.max, setting.step);
            break;
        case StyleSettingKind::Choice: {
            const int count = int(setting.choices.size());
            value = float((std::clamp(int(value), 0, count - 1) + direction + count) % count);
            break;
        }
    }
    host_.cvars().set(*cvar, format_number(value), CvarSource::kUser);
    build_rows();
}

void Menu::cycle_style(int direction) {
    const std::vector<std::string> styles = services_.styles();
    if (styles.empty()) return;
    const auto current = std::find(styles.begin(), styles.end(), services_.active_style());
    const int count = int(styles.size());
    const int index = current == styles.end() ? 0 : int(current - styles.begin());
    const std::string& next = styles[size_t((index + direction + count) % count)];
    run("r_plugin " + next);
    // The swap runs from the command buffer this frame; the row shows what was asked for.
    rows_[size_t(cursor_)].value = next;
}

void Menu::run(const std::string& text) {
    host_.commands().add_text(text + "\n");
}

}  // namespace nq

// Quake's menu (ESC): Main (Single Player, Multiplayer, Options, Help, Quit), Single Player
// (New Game, Load, Save), the twelve load/save slots, Options (console, defaults, screen size,
// brightness, mouse speed, field of view, volumes, always run, invert mouse, mouse look, the
// renderer style and the style's own settings page), Help and the quit question.
//
// The menu is state and rules only: no GL, no window. The engine hands it key names while it is
// active and draws it with menu_drawing.h; what the menu does happens through cvars and the
// command buffer (`map start`, `load s3`, `r_plugin technical`, `quit`), as a player typing
// would, so every menu action is also a console command away.
//
// Commands: togglemenu, menu_main, menu_singleplayer, menu_load, menu_save, menu_options,
// menu_style, menu_quit, help, menu_multiplayer.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "host/host_core.h"
#include "plugin/style_settings.h"

namespace nq {

enum class MenuScreen : uint8_t {
    None,
    Main,
    SinglePlayer,
    Load,
    Save,
    Options,
    Style,  // the active renderer style's settings
    Help,
    Quit,
};

inline constexpr int kSaveSlots = 12;  // s0 .. s11, as Quake's load/save menus

// What the menu asks of the engine besides cvars and commands.
class MenuServices {
  public:
    virtual ~MenuServices() = default;
    virtual std::vector<std::string> styles() const = 0;  // renderer plugins, sorted
    virtual std::string active_style() const = 0;
    virtual std::vector<StyleSetting> style_settings() const = 0;  // of the active style
    // The comment of save slot `slot` (s<slot>.sav), "" when there is none.
    virtual std::string save_comment(int slot) const = 0;
    virtual bool game_running() const = 0;  // a local game that could be saved
};

// One line of the current screen.
struct MenuRow {
    std::string label;
    std::string value;            // shown right of the label ("" for none)
    std::optional<float> slider;  // a slider's position, 0..1
    bool enabled = true;          // disabled rows are skipped by the cursor
};

class Menu {
  public:
    Menu(HostCore& host, MenuServices& services);
    ~Menu();
    Menu(const Menu&) = delete;
    Menu& operator=(const Menu&) = delete;

    bool active() const { return screen_ != MenuScreen::None; }
    MenuScreen screen() const { return screen_; }
    int cursor() const { return cursor_; }
    const std::vector<MenuRow>& rows() const { return rows_; }
    // A line under the rows (e.g. why an item cannot be chosen); cleared by the next key.
    const std::string& notice() const { return notice_; }
    int help_page() const { return help_page_; }
    int help_pages() const { return help_pages_; }
    // How many help pictures the game data has (help0.lmp ...); 0 shows a text page.
    void set_help_pages(int pages) { help_pages_ = pages; }

    void open(MenuScreen screen);
    void close() { open(MenuScreen::None); }
    // Quake's togglemenu: closes the main menu, goes back to it from the others, opens it.
    void toggle();

    // A key went down while the menu is active (Quake's key names: UPARROW, ENTER, ESCAPE,
    // MOUSE1, MWHEELUP, y, ...). Every key is the menu's while it is open.
    void key_down(std::string_view key);
    // The pointer is over row `row` of the current screen (-1: over none).
    void point_at(int row);

  private:
    void register_commands();
    void build_rows();
    void move_cursor(int step);
    void activate();
    void adjust(int direction);
    void back();
    void adjust_option(int direction);
    void adjust_style_setting(int direction);
    void cycle_style(int direction);
    void run(const std::string& text);

    HostCore& host_;
    MenuServices& services_;
    MenuScreen screen_ = MenuScreen::None;
    int cursor_ = 0;
    int help_page_ = 0;
    int help_pages_ = 0;
    std::vector<MenuRow> rows_;
    std::vector<int> option_ids_;  // Options: which option each row is
    std::vector<StyleSetting> style_settings_;
    std::string notice_;
    std::vector<std::string> added_commands_;
};

}  // namespace nq

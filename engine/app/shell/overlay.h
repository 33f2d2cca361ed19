// What the engine draws over every frame, whatever the plugin: the status bar and screen tints
// (the HUD), the menu and the console, with what they need: the console's font from gfx.wad,
// the HUD's pictures, the menu's view of the engine (styles, save slots). It says which input
// events are the menu's and whether something is open (a single-player game then waits and
// the mouse is free).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/shell/game_data.h"
#include "app/shell/menu_services.h"
#include "console/console.h"
#include "console/console_drawer.h"
#include "hud/hud.h"
#include "menu/menu.h"
#include "video/input_event.h"

namespace nq {

class Overlay {
  public:
    // Creates the console (sized to the screen) and the HUD with their pictures (GL objects:
    // after the window). What went wrong loading them: take_start_messages().
    Overlay(HostCore& host, const GameData& data, const Vfs* vfs, int width, int height);
    ~Overlay();
    Overlay(const Overlay&) = delete;
    Overlay& operator=(const Overlay&) = delete;

    // The menu, once the plugins it lists and the session it saves exist; `save_dir` holds
    // the save slots (<userdir>/<game>).
    void create_menu(const PluginHost& plugins, const DemoSession& session, std::string save_dir);
    std::vector<std::string> take_start_messages() { return std::move(start_messages_); }

    Console& console() { return *console_; }
    Hud& hud() { return *hud_; }
    Menu& menu() { return *menu_; }
    // The menu or the console is open: a single-player game waits, the mouse is free.
    bool open() const { return menu_->active() || console_->is_open(); }

    // ESCAPE opens the menu (or goes back in it; closes the console first when that is open);
    // every other key goes to the open menu, except the console's own key. True when the
    // event is the menu's. `session_active`: closing the console over nothing opens the menu.
    bool menu_takes_event(const InputEvent& event, bool session_active, const HudScreen& screen);
    // The menu and the console over the frame (the HUD is drawn with the 3D view).
    void draw(double real_time, const HudScreen& screen);

  private:
    HostCore& host_;
    std::unique_ptr<Console> console_;
    std::optional<ConsoleDrawer> console_drawer_;
    std::unique_ptr<Hud> hud_;
    std::unique_ptr<EngineMenuServices> menu_services_;
    std::unique_ptr<Menu> menu_;  // after hud_, whose pictures it shows
    std::vector<std::string> start_messages_;
};

}  // namespace nq

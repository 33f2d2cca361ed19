// What the menu (menu/menu.h) asks of the engine: the renderer plugins and the active one's
// settings, the save slots in the user directory, whether a local game runs.
#pragma once

#include <string>
#include <vector>

#include "app/sessions/demo_session.h"
#include "menu/menu.h"
#include "plugin/plugin_host.h"

namespace nq {

class EngineMenuServices : public MenuServices {
  public:
    // `save_dir`: <userdir>/<game>, where `save` writes s0.sav .. s11.sav.
    EngineMenuServices(const PluginHost& plugins, const DemoSession& demo, std::string save_dir);

    std::vector<std::string> styles() const override;
    std::string active_style() const override;
    std::vector<StyleSetting> style_settings() const override;
    std::string save_comment(int slot) const override;
    bool game_running() const override;

  private:
    const PluginHost& plugins_;
    const DemoSession& demo_;
    std::string save_dir_;
};

}  // namespace nq

// The engine's overlays on the game screen, as the engine uses them: the cvars (hud_cvars.h),
// the +showscores / -showscores commands, the pictures from the game data and the drawer.
//
//   Hud hud(host);                                  // cvars and commands
//   hud.load_pictures(gfx_wad, palette, vfs);        // GL context current; returns what to say
//   every demo frame, right after the 3D view:
//     hud.draw(client, view.eye_contents, width, height, real_time);  // tints, then the bars
//
// Destroy it before the HostCore and while the GL context is still current.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "client/client_state.h"
#include "host/host_core.h"
#include "hud/hud_cvars.h"
#include "hud/hud_drawer.h"

namespace nq {

class Vfs;

class Hud {
  public:
    explicit Hud(HostCore& host);
    ~Hud();
    Hud(const Hud&) = delete;
    Hud& operator=(const Hud&) = delete;

    // Creates the drawer and loads the pictures (none without gfx.wad and a palette: then
    // only the screen tints are drawn). Returns lines for the console: what is missing or
    // broken, and why the drawer could not be made.
    std::vector<std::string> load_pictures(const Wad* gfx_wad, const Palette* palette,
                                           const Vfs* vfs);

    float viewsize() const { return cvars_.viewsize->value(); }
    HudSettings settings() const;

    // The view blend (unless gl_polyblend is 0), then the status bar and the rest (unless
    // scr_drawhud is 0), over a width x height screen.
    void draw(const ClientState& client, int eye_contents, int width, int height, double real_time);
    // Counts a drawn frame for scr_showfps (the engine calls it once per frame it draws).
    void count_frame(double real_time);

    const HudDrawer* drawer() const { return drawer_ ? &*drawer_ : nullptr; }
    // Draws another overlay with the HUD's pictures (HudDrawer::draw_overlay).
    template <typename Build>
    void draw_overlay(int width, int height, Build&& build) {
        if (drawer_) drawer_->draw_overlay(width, height, std::forward<Build>(build));
    }

  private:
    static constexpr float kViewsizeStep = 10.0f;
    void add_command(const char* name, CommandFn fn, const char* description);
    void step_viewsize(float step);

    HostCore& host_;
    HudCvars cvars_;
    std::optional<HudDrawer> drawer_;
    bool show_scores_ = false;
    // scr_showfps: frames counted since the second began at fps_since_.
    int fps_frames_ = 0;
    double fps_since_ = -1;
    float fps_ = 0;
    std::vector<std::string> added_commands_;  // only what it added is removed again
};

}  // namespace nq

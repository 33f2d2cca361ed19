// The frame wing of the engine: the renderer plugins (the services they call, the plugin host,
// the dispatch that fills the hooks a plugin leaves out), the models they hold (a session's
// level or the built-in showroom, never both), and the frame drawn each time: the view from
// the session's client (view state, camera, the scene's nqr_frame) or the showroom's. The
// engine shell gives it the settings read from cvars this frame (FrameSettings) and asks it
// to draw; what it keeps from the view is where sound is heard from.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <string_view>

#include "app/frame/host_services.h"
#include "app/frame/render_dispatch.h"
#include "app/frame/scene_builder.h"
#include "app/frame/showroom.h"
#include "app/sessions/level.h"
#include "client/client_state.h"
#include "client/view.h"
#include "obscurance/obscurance_settings.h"
#include "plugin/plugin_host.h"
#include "sound/client_sound_feed.h"

namespace nq {

struct Bsp;
class FrameTrace;
class GpuPassTimers;
class Vfs;
struct GameData;

// What the wing needs of the engine; the pointers outlive the renderer.
struct FrameRendererContext {
    HostCore* host = nullptr;
    const Vfs* vfs = nullptr;  // null without game data
    const GameData* game_data = nullptr;
    GpuPassTimers* gpu_timers = nullptr;
    FrameTrace* trace = nullptr;  // where the frame's stages are charged (-benchtrace; may be null)
    std::string plugin_dir;
    std::function<void(std::string_view)> print;
    // The session's world while a demo or game runs (a plugin's traces hit it); null otherwise.
    std::function<const Bsp*()> session_world;
};

// The settings of this frame, read from cvars and the screen by the shell.
struct FrameSettings {
    int width = 0;
    int height = 0;
    float fov_x = 90.0f;
    bool occlusion = true;         // r_occlusion, and a screen that is not multisampled
    float view_model_lift = 0.0f;  // r_viewmodel_quake's lift for the status bar's size
    bool draw_view_model = true;
    float showroom_time = -1.0f;  // >= 0 holds the showroom still at that time
    npr::obscurance::ObscuranceSettings obscurance;
};

class FrameRenderer {
  public:
    explicit FrameRenderer(FrameRendererContext context);
    ~FrameRenderer();
    FrameRenderer(const FrameRenderer&) = delete;
    FrameRenderer& operator=(const FrameRenderer&) = delete;

    PluginHost& plugins() { return *plugins_; }
    const PluginHost& plugins() const { return *plugins_; }
    RenderDispatch& dispatch() { return *dispatch_; }

    // Swaps to the plugin `name`: empty, or why it did not load (the current one stays).
    std::string load_plugin(const std::string& name) { return dispatch_->load_plugin(name); }
    // After a swap: the level on screen (if its models are registered) is drawn once at once,
    // so the new plugin's first-use costs land here, not in play.
    void warm_up_shown_level(Level& level, const FrameSettings& settings);

    // A session's level arrived (its models go to the renderer and a warm-up frame is drawn),
    // restarted (the models stay; the view starts afresh) or is going away.
    void register_level_models(Level& level, const FrameSettings& settings);
    void level_restarted(Level& level, const FrameSettings& settings);
    void release_level_models();
    void show_showroom(bool on);
    bool showroom_shown() const { return showroom_ != nullptr; }

    // Draws the session's level from its client's view; `paused` draws the instant drawn last
    // again. Returns the view (the HUD tints by its eye contents).
    ViewResult draw_level(Level& level, const ClientState& client, bool paused, double real_time,
                          float frame_time, const FrameSettings& settings);
    void draw_showroom(double real_time, float frame_time, const FrameSettings& settings);

    // Where the view drawn last hears from.
    const Listener& listener() const { return listener_; }

  private:
    void warm_up(Level& level, const FrameSettings& settings);
    void trace(const float start[3], const float end[3], nqr_trace* out) const;

    FrameRendererContext context_;
    std::unique_ptr<HostServices> services_;
    std::unique_ptr<PluginHost> plugins_;
    std::unique_ptr<RenderDispatch> dispatch_;
    SceneBuilder scene_;
    ViewState view_state_;
    std::unique_ptr<Showroom> showroom_;
    Listener listener_;
    bool level_models_registered_ = false;
    double paused_real_time_ = 0;  // wall clock of the level frame drawn last
};

}  // namespace nq

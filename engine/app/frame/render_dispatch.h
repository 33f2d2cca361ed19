// Draws a frame through the active renderer plugin. Every hook the plugin leaves NULL is drawn
// by the engine's own instance of nprlib's classic drawers, created when a plugin first needs it
// and released when a plugin that draws everything itself takes over. Each pass is timed with
// the GPU pass timers.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "app/frame/scene_framebuffer.h"
#include "nqr_renderer.h"
#include "obscurance/obscurance_pass.h"
#include "plugin/plugin_host.h"

namespace nq::npr::classic {
class ClassicRenderer;
}

namespace nq {

class GpuPassTimers;
class FrameTrace;

class RenderDispatch {
  public:
    RenderDispatch(PluginHost& plugins, GpuPassTimers* timers);
    ~RenderDispatch();

    // Swaps to `name` (see PluginHost::load), then makes the defaults match the new plugin.
    std::string load_plugin(const std::string& name);
    void unload();

    // Models go to the plugin and to the defaults (when they exist).
    void register_model(const nqr_model* model);
    void release_model(nqr_model_id id);
    void clear_models();

    void draw(const nqr_frame& frame);

    // The engine-wide volumetric obscurance settings for the next draws (vo_*).
    void set_obscurance(const npr::obscurance::ObscuranceSettings& settings) {
        obscurance_settings_ = settings;
    }

    bool defaults_active() const { return defaults_ != nullptr; }

    // vo_dump_scene: the next frame drawn also writes its geometry to `path` (scene_file.h),
    // for the ray-traced obscurance reference; `done` gets the message to print.
    void dump_scene_next_frame(std::string path, std::function<void(const std::string&)> done) {
        dump_path_ = std::move(path);
        dump_done_ = std::move(done);
    }

    // -benchtrace: each pass's CPU time is charged to its stage (may be null).
    void set_trace(FrameTrace* trace) { trace_ = trace; }

  private:
    bool plugin_draws_everything() const;
    void sync_defaults();
    void draw_scene(const nqr_renderer* r, const nqr_frame& frame);
    void bind_window(const nqr_frame& frame);
    void post_process(const nqr_renderer* r, const nqr_frame& frame);
    bool apply_obscurance(const nqr_frame& frame, bool onto_window);
    void dump_scene(const nqr_frame& frame);

    PluginHost& plugins_;
    GpuPassTimers* timers_;
    FrameTrace* trace_ = nullptr;
    std::unique_ptr<npr::classic::ClassicRenderer> defaults_;
    SceneFramebuffer gbuffer_;
    npr::obscurance::ObscuranceSettings obscurance_settings_;  // disabled by default
    npr::obscurance::ObscurancePass obscurance_;
    bool obscurance_failed_ = false;  // reported once; off for the rest of the run
    int reported_decisions_ = 0;      // the pass's vo_compute 2 choices told on the console
    std::string dump_path_;
    std::function<void(const std::string&)> dump_done_;
};

}  // namespace nq

#include "app/frame/frame_renderer.h"

#include <epoxy/gl.h>

#include <algorithm>

#include "app/shell/game_data.h"
#include "formats/bsp.h"
#include "video/frame_trace.h"
#include "video/video_window.h"

namespace nq {

namespace {

int contents_at(void* user, const Vec3& point) {
    const Bsp* bsp = static_cast<const Bsp*>(user);
    return bsp ? point_contents(*bsp, 0, {point[0], point[1], point[2]}) : 0;
}

bool developer(const HostCore& host) {
    const Cvar* cvar = host.cvars().find("developer");
    return cvar && cvar->value() != 0;
}

CameraSetup camera_for(const FrameSettings& settings) {
    CameraSetup camera;
    camera.fov_x = settings.fov_x;
    camera.viewport[2] = settings.width;
    camera.viewport[3] = settings.height;
    return camera;
}

}  // namespace

FrameRenderer::FrameRenderer(FrameRendererContext context) : context_(std::move(context)) {
    HostServicesWiring wiring;
    wiring.host = context_.host;
    wiring.vfs = context_.vfs;
    wiring.gpu_timers = context_.gpu_timers;
    wiring.log = [this](int, std::string_view text) { context_.print(text); };
    wiring.trace = [this](const float s[3], const float e[3], nqr_trace* out) { trace(s, e, out); };
    wiring.gl_proc_address = &VideoWindow::gl_proc_address;
    services_ = std::make_unique<HostServices>(std::move(wiring));
    auto palette = context_.game_data->palette_bytes();
    uint8_t pal[768];
    std::copy(palette.begin(), palette.end(), pal);
    services_->set_palette(pal);
    if (const auto& colormap = context_.game_data->colormap) {
        services_->set_colormap(colormap->table.data(), colormap->table.size());
    }
    plugins_ = std::make_unique<PluginHost>(*services_, context_.plugin_dir);
    dispatch_ = std::make_unique<RenderDispatch>(*plugins_, context_.gpu_timers);
    if (context_.trace && context_.trace->enabled()) dispatch_->set_trace(context_.trace);
}

FrameRenderer::~FrameRenderer() {
    dispatch_.reset();  // the defaults and passes go before the plugin host
    plugins_.reset();
}

// A plugin's trace: the showroom's floor while it is shown and no session runs, else the
// session's world (fraction 1 when there is none).
void FrameRenderer::trace(const float s[3], const float e[3], nqr_trace* out) const {
    const Bsp* bsp = context_.session_world();
    if (showroom_ && !bsp) return Showroom::trace(s, e, out);
    if (!bsp) return;
    BspTrace t = trace_hull(*bsp, 0, {s[0], s[1], s[2]}, {e[0], e[1], e[2]});
    out->fraction = t.fraction;
    for (int k = 0; k < 3; ++k) {
        out->end[k] = t.end[k];
        out->plane_normal[k] = t.plane_normal[k];
    }
    out->plane_dist = t.plane_dist;
    out->start_solid = t.start_solid ? 1 : 0;
}

void FrameRenderer::warm_up_shown_level(Level& level, const FrameSettings& settings) {
    if (level_models_registered_) warm_up(level, settings);
}

void FrameRenderer::register_level_models(Level& level, const FrameSettings& settings) {
    show_showroom(false);
    scene_.bind_level(level);
    for (const auto& model : level.models().models()) dispatch_->register_model(model->abi());
    level_models_registered_ = true;
    warm_up(level, settings);
    view_state_ = {};
    if (developer(*context_.host)) {
        const AmbientCubeField* field = level.ambient_field();
        context_.print("ambient cube field: " +
                       std::to_string(field ? field->samples().size() : 0) + " samples baked in " +
                       std::to_string(int(level.ambient_bake_seconds() * 1000.0)) + " ms");
    }
}

// Draws the level's warm-up frame (SceneBuilder::build_warm_up) and waits for it, so the
// driver's first-use costs land at load; the next frame clears it before anything shows.
void FrameRenderer::warm_up(Level& level, const FrameSettings& settings) {
    if (!level.loaded()) return;
    glViewport(0, 0, settings.width, settings.height);
    dispatch_->set_obscurance(settings.obscurance);
    dispatch_->draw(scene_.build_warm_up(level, camera_for(settings)));
    glFinish();
}

// The renderer keeps the models it has; only what belongs to the view starts afresh.
void FrameRenderer::level_restarted(Level& level, const FrameSettings& settings) {
    if (!level_models_registered_) return register_level_models(level, settings);
    view_state_ = {};
    if (developer(*context_.host)) {
        context_.print("map restarted: the level and its " +
                       std::to_string(level.models().models().size()) + " models kept");
    }
}

void FrameRenderer::release_level_models() {
    if (!level_models_registered_) return;
    dispatch_->clear_models();
    level_models_registered_ = false;
}

void FrameRenderer::show_showroom(bool on) {
    if (on == (showroom_ != nullptr)) return;
    if (on) {
        release_level_models();
        showroom_ = std::make_unique<Showroom>();
        showroom_->assign_ids(1);
        for (const nqr_model* m : showroom_->models()) dispatch_->register_model(m);
    } else {
        dispatch_->clear_models();
        showroom_.reset();
    }
}

ViewResult FrameRenderer::draw_level(Level& level, const ClientState& client, bool paused,
                                     double real_time, float frame_time,
                                     const FrameSettings& settings) {
    if (paused) {  // the instant drawn last, its wall clock included
        real_time = paused_real_time_;
        frame_time = 0;
    }
    paused_real_time_ = real_time;
    ViewSettings view_settings;
    view_settings.contents_at = &contents_at;
    view_settings.contents_user = const_cast<Bsp*>(level.world_bsp());
    view_settings.view_model_lift = settings.view_model_lift;
    view_settings.draw_view_model = settings.draw_view_model;
    ViewResult view = compute_view(client, view_state_, view_settings);
    listener_ = listener_for_view(view.origin, view.angles, client.view_entity());
    scene_.set_occlusion_culling(settings.occlusion);
    CameraSetup camera = camera_for(settings);
    camera.origin = {view.origin[0], view.origin[1], view.origin[2]};
    camera.angles = {view.angles[0], view.angles[1], view.angles[2]};
    const nqr_frame& frame = scene_.build(level, client, view, camera, real_time, frame_time);
    if (context_.trace) {
        context_.trace->set_contents(
            {frame.num_brush_entities + frame.num_alias_entities + frame.num_sprite_entities,
             frame.num_dlights, frame.num_particles});
        context_.trace->lap(TraceStage::Scene);
    }
    dispatch_->set_obscurance(settings.obscurance);
    dispatch_->draw(frame);
    return view;
}

void FrameRenderer::draw_showroom(double real_time, float frame_time,
                                  const FrameSettings& settings) {
    if (!showroom_) return;
    CameraSetup camera = Showroom::default_camera(settings.width, settings.height);
    camera.fov_x = settings.fov_x;
    if (settings.showroom_time >= 0) {  // a still scene
        real_time = settings.showroom_time;
        frame_time = 0;
    }
    dispatch_->set_obscurance(settings.obscurance);
    dispatch_->draw(showroom_->build(scene_, camera, real_time, real_time, frame_time));
}

}  // namespace nq

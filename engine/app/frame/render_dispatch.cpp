#include "app/frame/render_dispatch.h"

#include <algorithm>
#include <utility>

#include <epoxy/gl.h>

#include "classic/classic_renderer.h"
#include "common/file_io.h"
#include "obscurance/scene_triangles.h"
#include "video/frame_trace.h"
#include "video/gpu_pass_timers.h"

namespace nq {

namespace {

using Hook = void (*)(void* self, const nqr_frame*);
using DefaultHook = void (npr::classic::ClassicRenderer::*)(const nqr_frame*);

struct Pass {
    GpuPass pass;
    TraceStage stage;
    Hook nqr_renderer::*hook;
    DefaultHook fallback;
};

constexpr Pass kPasses[] = {
    {GpuPass::World, TraceStage::World, &nqr_renderer::draw_world,
     &npr::classic::ClassicRenderer::draw_world},
    {GpuPass::Brush, TraceStage::Brush, &nqr_renderer::draw_brush_entities,
     &npr::classic::ClassicRenderer::draw_brush_entities},
    {GpuPass::Alias, TraceStage::Alias, &nqr_renderer::draw_alias_entities,
     &npr::classic::ClassicRenderer::draw_alias_entities},
    {GpuPass::Sprites, TraceStage::Sprites, &nqr_renderer::draw_sprite_entities,
     &npr::classic::ClassicRenderer::draw_sprite_entities},
    {GpuPass::Particles, TraceStage::Particles, &nqr_renderer::draw_particles,
     &npr::classic::ClassicRenderer::draw_particles},
};

}  // namespace

RenderDispatch::RenderDispatch(PluginHost& plugins, GpuPassTimers* timers)
    : plugins_(plugins), timers_(timers) {
    if (!timers_) return;
    // Each obscurance stage timed on its own, inside the "obscurance" pass.
    npr::obscurance::PassMarkers markers;
    markers.begin = [](void* context, const char* stage) {
        static_cast<GpuPassTimers*>(context)->begin(stage);
    };
    markers.end = [](void* context) { static_cast<GpuPassTimers*>(context)->end(); };
    markers.context = timers_;
    obscurance_.set_markers(markers);
}

RenderDispatch::~RenderDispatch() {
    unload();
}

std::string RenderDispatch::load_plugin(const std::string& name) {
    std::string why = plugins_.load(name);
    if (why.empty()) sync_defaults();
    return why;
}

void RenderDispatch::unload() {
    plugins_.unload();
    defaults_.reset();
    gbuffer_.release();
}

bool RenderDispatch::plugin_draws_everything() const {
    const nqr_renderer* r = plugins_.active();
    if (!r) return false;
    for (const Pass& p : kPasses) {
        if (!(r->*p.hook)) return false;
    }
    return true;
}

void RenderDispatch::sync_defaults() {
    if (plugin_draws_everything()) {
        defaults_.reset();
        return;
    }
    if (defaults_) return;
    auto fresh = std::make_unique<npr::classic::ClassicRenderer>();
    std::string error;
    if (!fresh->init(&plugins_.engine_services().table(), &error)) {
        plugins_.engine_services().log(NQR_LOG_ERROR,
                                       ("default renderer failed: " + error).c_str());
        return;
    }
    for (const nqr_model* m : plugins_.models()) fresh->register_model(m);
    defaults_ = std::move(fresh);
}

void RenderDispatch::register_model(const nqr_model* model) {
    plugins_.register_model(model);
    if (defaults_) defaults_->register_model(model);
}

void RenderDispatch::release_model(nqr_model_id id) {
    plugins_.release_model(id);
    if (defaults_) defaults_->release_model(id);
}

void RenderDispatch::clear_models() {
    while (!plugins_.models().empty()) release_model(plugins_.models().back()->id);
}

void RenderDispatch::draw(const nqr_frame& frame) {
    const nqr_renderer* r = plugins_.active();
    // Obscurance reads the scene's depth and normals, so it draws into the G-buffer too.
    const bool obscurance = obscurance_settings_.enabled && !obscurance_failed_;
    const bool wants_gbuffer = (r && (r->wants & NQR_WANTS_GBUFFER)) || obscurance;
    const bool use_gbuffer =
        wants_gbuffer && gbuffer_.prepare(frame.camera->viewport[2], frame.camera->viewport[3]);
    if (use_gbuffer) gbuffer_.bind_and_clear();
    if (r && r->begin_frame) r->begin_frame(plugins_.active_self(), &frame);
    draw_scene(r, frame);
    if (use_gbuffer) {
        // Without a plugin post-process the obscurance composite writes the window itself,
        // which saves the copy of the scene that would follow it.
        const bool onto_window = obscurance && apply_obscurance(frame, !(r && r->post_process));
        if (trace_) trace_->lap(TraceStage::Obscurance);
        if (onto_window)
            bind_window(frame);
        else
            post_process(r, frame);
    }
    if (r && r->end_frame) r->end_frame(plugins_.active_self(), &frame);
    if (trace_) trace_->lap(TraceStage::Post);
    if (!dump_path_.empty()) dump_scene(frame);
}

void RenderDispatch::dump_scene(const nqr_frame& frame) {
    const std::string path = std::exchange(dump_path_, {});
    const npr::obscurance::ObscuranceScene scene =
        npr::obscurance::collect_scene(frame, plugins_.models());
    const std::string error = write_file(path, npr::obscurance::encode_scene(scene));
    if (dump_done_) {
        dump_done_(error.empty() ? "vo_dump_scene: wrote " + path + " (" +
                                       std::to_string(scene.triangles.size()) + " triangles)"
                                 : "vo_dump_scene: " + error);
    }
}

void RenderDispatch::draw_scene(const nqr_renderer* r, const nqr_frame& frame) {
    for (const Pass& p : kPasses) {
        Hook hook = r ? r->*p.hook : nullptr;
        if (!hook && !defaults_) continue;
        if (timers_) timers_->begin(p.pass);
        if (hook) {
            hook(plugins_.active_self(), &frame);
        } else {
            ((*defaults_).*p.fallback)(&frame);
        }
        if (timers_) timers_->end();
        if (trace_) trace_->lap(p.stage);
    }
}

void RenderDispatch::bind_window(const nqr_frame& frame) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    const int* vp = frame.camera->viewport;
    glViewport(vp[0], vp[1], vp[2], vp[3]);
}

// Back on the window: the plugin's post-process pass reads the scene textures and draws the
// final image; without one, the colour is copied over as it is.
void RenderDispatch::post_process(const nqr_renderer* r, const nqr_frame& frame) {
    const nqr_gbuffer& g = gbuffer_.gbuffer();
    bind_window(frame);
    const int* vp = frame.camera->viewport;
    if (timers_) timers_->begin(GpuPass::Post);
    if (r && r->post_process) {
        r->post_process(plugins_.active_self(), &frame, &g);
    } else {
        glBindFramebuffer(GL_READ_FRAMEBUFFER, g.framebuffer);
        glReadBuffer(GL_COLOR_ATTACHMENT0);
        glBlitFramebuffer(0, 0, g.width, g.height, vp[0], vp[1], vp[0] + vp[2], vp[1] + vp[3],
                          GL_COLOR_BUFFER_BIT, GL_NEAREST);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    }
    if (timers_) timers_->end();
}

// Before the plugin's post-process (or the copy to the window): the scene colour multiplied by
// its obscurance, in the G-buffer or, `onto_window`, straight onto the window's viewport (true
// when it did). A pass that cannot build is reported once and stays off.
bool RenderDispatch::apply_obscurance(const nqr_frame& frame, bool onto_window) {
    const nqr_gbuffer& g = gbuffer_.gbuffer();
    npr::obscurance::SceneTextures scene;
    scene.framebuffer = g.framebuffer;
    scene.colour_texture = g.color_texture;
    scene.depth_texture = g.depth_texture;
    scene.normal_texture = g.normal_texture;
    scene.width = g.width;
    scene.height = g.height;
    std::copy_n(frame.camera->projection, 16, scene.projection);
    npr::obscurance::CompositeTarget window;
    std::copy_n(frame.camera->viewport, 4, window.viewport);
    if (timers_) timers_->begin("obscurance");
    std::string error;
    const bool applied =
        obscurance_.apply(scene, obscurance_settings_, error, onto_window ? &window : nullptr);
    if (!applied) {
        obscurance_failed_ = true;
        plugins_.engine_services().log(NQR_LOG_ERROR, ("obscurance off: " + error).c_str());
    }
    if (timers_) timers_->end();
    if (obscurance_.decisions() != reported_decisions_) {  // vo_compute 2 made its choice
        reported_decisions_ = obscurance_.decisions();
        const std::string choice = npr::obscurance::describe_choice(obscurance_.trial());
        plugins_.engine_services().log(
            NQR_LOG_INFO, ("obscurance estimate and blur (vo_compute 2): " + choice).c_str());
    }
    return applied && onto_window;
}

}  // namespace nq

// The `classic` renderer plugin: the faithful GLQuake look, drawn entirely by nprlib's classic
// drawers. It implements every hook itself, so the engine's defaults stay idle while it runs.
#include <memory>
#include <string>

#include "abi/plugin_entry.h"
#include "abi/plugin_instances.h"
#include "classic/classic_renderer.h"
#include "nqr_renderer.h"

namespace {

using nq::npr::classic::ClassicRenderer;

// The plugin's state: one renderer per init, retired by shutdown (see plugin_instances.h).
nq::npr::PluginInstances<ClassicRenderer> g_renderers;

int classic_init(const nqr_engine* engine) {
    auto renderer = std::make_unique<ClassicRenderer>();
    std::string error;
    if (!renderer->init(engine, &error)) return 1;  // init() logged why
    g_renderers.add(std::move(renderer));
    return 0;
}

void classic_shutdown() {
    g_renderers.retire_oldest();
}
void classic_register(const nqr_model* m) {
    g_renderers.current().register_model(m);
}
void classic_release(nqr_model_id id) {
    g_renderers.current().release_model(id);
}
void classic_world(const nqr_frame* f) {
    g_renderers.current().draw_world(f);
}
void classic_brush(const nqr_frame* f) {
    g_renderers.current().draw_brush_entities(f);
}
void classic_alias(const nqr_frame* f) {
    g_renderers.current().draw_alias_entities(f);
}
void classic_sprites(const nqr_frame* f) {
    g_renderers.current().draw_sprite_entities(f);
}
void classic_particles(const nqr_frame* f) {
    g_renderers.current().draw_particles(f);
}

const nqr_renderer kTable = {
    sizeof(nqr_renderer),
    NQR_ABI_VERSION,
    "classic",
    "the GLQuake look: textures, lightmaps, sky, liquids, models, sprites, particles",
    0,
    classic_init,
    classic_shutdown,
    classic_register,
    classic_release,
    nullptr,  // begin_frame
    classic_world,
    classic_brush,
    classic_alias,
    classic_sprites,
    classic_particles,
    nullptr,  // post_process
    nullptr,  // end_frame
    nullptr,  // menu_settings: classic has no settings of its own
    0,
};

}  // namespace

extern "C" NQR_EXPORT const nqr_renderer* nqr_get_renderer(uint32_t engine_abi_version,
                                                           const nqr_engine* engine) {
    return nq::npr::engine_abi_compatible(engine_abi_version, engine) ? &kTable : nullptr;
}

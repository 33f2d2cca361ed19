// The `technical` renderer plugin: technical illustration of Quake, drawn by nprlib's
// TechnicalRenderer (classic world textures underneath, NPR models and edges on top). The
// plugin's own job is the ABI shell and the cvars (technical_cvars.h), read every frame.
#include <memory>
#include <string>

#include "abi/plugin_entry.h"
#include "abi/plugin_instances.h"
#include "nqr_renderer.h"
#include "technical/technical_cvars.h"
#include "technical/technical_renderer.h"

namespace {

using nq::npr::technical::TechnicalCvars;
using nq::npr::technical::TechnicalRenderer;

// The plugin's state: one per init, retired by shutdown (see plugin_instances.h).
struct Plugin {
    TechnicalRenderer renderer;
    TechnicalCvars cvars;
};
nq::npr::PluginInstances<Plugin> g_plugins;

int technical_init(const nqr_engine* engine) {
    auto plugin = std::make_unique<Plugin>();
    std::string error;
    if (!plugin->renderer.init(engine, &error)) return 1;  // init() logged why
    plugin->cvars.register_all(*engine);
    plugin->cvars.update(plugin->renderer.settings);
    g_plugins.add(std::move(plugin));
    return 0;
}

void technical_shutdown() {
    g_plugins.retire_oldest();
}
void technical_register(const nqr_model* m) {
    g_plugins.current().renderer.register_model(m);
}
void technical_release(nqr_model_id id) {
    g_plugins.current().renderer.release_model(id);
}
void technical_begin(const nqr_frame*) {
    g_plugins.current().cvars.update(g_plugins.current().renderer.settings);
}
void technical_world(const nqr_frame* f) {
    g_plugins.current().renderer.draw_world(f);
}
void technical_brush(const nqr_frame* f) {
    g_plugins.current().renderer.draw_brush_entities(f);
}
void technical_alias(const nqr_frame* f) {
    g_plugins.current().renderer.draw_alias_entities(f);
}
void technical_sprites(const nqr_frame* f) {
    g_plugins.current().renderer.draw_sprite_entities(f);
}
void technical_particles(const nqr_frame* f) {
    g_plugins.current().renderer.draw_particles(f);
}

const nqr_renderer kTable = {
    sizeof(nqr_renderer),
    NQR_ABI_VERSION,
    "technical",
    "technical illustration: silhouettes, creases, Gooch shading, umbra/penumbra shadows",
    0,
    technical_init,
    technical_shutdown,
    technical_register,
    technical_release,
    technical_begin,
    technical_world,
    technical_brush,
    technical_alias,
    technical_sprites,
    technical_particles,
    nullptr,  // post_process
    nullptr,  // end_frame
    nq::npr::technical::technical_menu_settings().data(),
    static_cast<uint32_t>(nq::npr::technical::technical_menu_settings().size()),
};

}  // namespace

extern "C" NQR_EXPORT const nqr_renderer* nqr_get_renderer(uint32_t engine_abi_version,
                                                           const nqr_engine* engine) {
    return nq::npr::engine_abi_compatible(engine_abi_version, engine) ? &kTable : nullptr;
}

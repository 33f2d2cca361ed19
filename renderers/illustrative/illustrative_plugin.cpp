// The `illustrative` renderer plugin: Team Fortress 2's illustrative shading on Quake, drawn by
// nprlib's IllustrativeRenderer (classic world with abstracted textures underneath, TF2-shaded
// models on top). The plugin's own job is the ABI shell and the cvars (illustrative_cvars.h),
// read every frame.
#include <memory>
#include <string>

#include "abi/plugin_entry.h"
#include "abi/plugin_instances.h"
#include "illustrative/illustrative_cvars.h"
#include "illustrative/illustrative_renderer.h"
#include "nqr_renderer.h"

namespace {

using nq::npr::illustrative::IllustrativeCvars;
using nq::npr::illustrative::IllustrativeRenderer;

// The plugin's state: one per init, retired by shutdown (see plugin_instances.h).
struct Plugin {
    IllustrativeRenderer renderer;
    IllustrativeCvars cvars;
};
nq::npr::PluginInstances<Plugin> g_plugins;

int illustrative_init(const nqr_engine* engine) {
    auto plugin = std::make_unique<Plugin>();
    // Cvars first: the ramp and the world abstraction are chosen from them at init and load.
    plugin->cvars.register_all(*engine);
    plugin->cvars.update(plugin->renderer.settings);
    std::string error;
    if (!plugin->renderer.init(engine, &error)) return 1;  // init() logged why
    g_plugins.add(std::move(plugin));
    return 0;
}

void illustrative_shutdown() {
    g_plugins.retire_oldest();
}
void illustrative_register(const nqr_model* m) {
    g_plugins.current().renderer.register_model(m);
}
void illustrative_release(nqr_model_id id) {
    g_plugins.current().renderer.release_model(id);
}
void illustrative_begin(const nqr_frame*) {
    Plugin& plugin = g_plugins.current();
    plugin.cvars.update(plugin.renderer.settings);
    plugin.renderer.begin_frame();
}
void illustrative_world(const nqr_frame* f) {
    g_plugins.current().renderer.draw_world(f);
}
void illustrative_brush(const nqr_frame* f) {
    g_plugins.current().renderer.draw_brush_entities(f);
}
void illustrative_alias(const nqr_frame* f) {
    g_plugins.current().renderer.draw_alias_entities(f);
}
void illustrative_sprites(const nqr_frame* f) {
    g_plugins.current().renderer.draw_sprite_entities(f);
}
void illustrative_particles(const nqr_frame* f) {
    g_plugins.current().renderer.draw_particles(f);
}

const nqr_renderer kTable = {
    sizeof(nqr_renderer),
    NQR_ABI_VERSION,
    "illustrative",
    "Team Fortress 2's illustrative shading: warped diffuse, ambient cubes, rim light",
    0,
    illustrative_init,
    illustrative_shutdown,
    illustrative_register,
    illustrative_release,
    illustrative_begin,
    illustrative_world,
    illustrative_brush,
    illustrative_alias,
    illustrative_sprites,
    illustrative_particles,
    nullptr,  // post_process
    nullptr,  // end_frame
    nq::npr::illustrative::illustrative_menu_settings().data(),
    static_cast<uint32_t>(nq::npr::illustrative::illustrative_menu_settings().size()),
};

}  // namespace

extern "C" NQR_EXPORT const nqr_renderer* nqr_get_renderer(uint32_t engine_abi_version,
                                                           const nqr_engine* engine) {
    return nq::npr::engine_abi_compatible(engine_abi_version, engine) ? &kTable : nullptr;
}

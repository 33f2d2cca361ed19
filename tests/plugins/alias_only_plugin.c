/* A renderer plugin for the engine tests that draws alias models only: every other draw hook is
 * present and does nothing, and draw_alias_entities is left NULL, so the engine draws the alias
 * models with its default (classic) drawer onto the cleared, black screen. A screenshot then
 * shows exactly where the engine put its models, with no world in front of or behind them.
 * Built as nqr_test_alias_only.so into its own directory (build/<preset>/tests/plugins/
 * alias_only), so the plugin-host tests' listing of the misbehaving plugins stays as it is. */
#include "nqr_renderer.h"

/* It keeps no state: its instance is the engine's table, which outlives it. */
static void* alias_only_init(const nqr_engine* engine) {
    engine->log(engine->context, NQR_LOG_INFO,
                "alias_only renderer: only alias models will be drawn");
    return (void*)engine;
}

static void alias_only_shutdown(void* self) {
    (void)self;
}
static void alias_only_register(void* self, const nqr_model* model) {
    (void)self;
    (void)model;
}
static void alias_only_release(void* self, nqr_model_id id) {
    (void)self;
    (void)id;
}
static void draw_nothing(void* self, const nqr_frame* frame) {
    (void)self;
    (void)frame;
}

static const nqr_renderer g_table = {
    sizeof(nqr_renderer),
    NQR_ABI_VERSION,
    "alias_only",
    "draws alias models only, with the engine's default drawer (engine tests)",
    0,
    alias_only_init,
    alias_only_shutdown,
    alias_only_register,
    alias_only_release,
    0,            /* begin_frame */
    draw_nothing, /* draw_world */
    draw_nothing, /* draw_brush_entities */
    0,            /* draw_alias_entities: the engine's default drawer */
    draw_nothing, /* draw_sprite_entities */
    draw_nothing, /* draw_particles */
    0,            /* post_process */
    0,            /* end_frame */
    0,            /* menu_settings */
    0,            /* num_menu_settings */
};

NQR_EXPORT const nqr_renderer* nqr_get_renderer(uint32_t engine_abi_version,
                                                const nqr_engine* engine) {
    if (NQR_ABI_MAJOR(engine_abi_version) != NQR_ABI_VERSION_MAJOR || !engine) return 0;
    return &g_table;
}

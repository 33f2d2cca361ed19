/* The null renderer: every draw hook is present and does nothing, so the engine draws nothing
 * (a NULL hook would make the engine draw that part with its defaults). It touches no GL, which
 * makes it the renderer for engine tests, for timing the engine without drawing, and the
 * smallest example of the plugin ABI — written in C to show the boundary needs no C++. */
#include "nqr_renderer.h"

static const nqr_engine* g_engine;
static unsigned g_models;

static int null_init(const nqr_engine* engine) {
    g_engine = engine;
    g_models = 0;
    engine->log(NQR_LOG_INFO, "null renderer: nothing will be drawn");
    return 0;
}

static void null_shutdown(void) { g_engine = 0; }
static void null_register_model(const nqr_model* model) { (void)model; ++g_models; }
static void null_release_model(nqr_model_id id) { (void)id; --g_models; }
static void null_frame(const nqr_frame* frame) { (void)frame; }
static void null_post(const nqr_frame* frame, const nqr_gbuffer* g) { (void)frame; (void)g; }

static const nqr_renderer g_table = {
    sizeof(nqr_renderer),
    NQR_ABI_VERSION,
    "null",
    "draws nothing, uses no GL (engine tests, CPU timing)",
    0,
    null_init,
    null_shutdown,
    null_register_model,
    null_release_model,
    null_frame, /* begin_frame */
    null_frame, /* draw_world */
    null_frame, /* draw_brush_entities */
    null_frame, /* draw_alias_entities */
    null_frame, /* draw_sprite_entities */
    null_frame, /* draw_particles */
    null_post,
    null_frame, /* end_frame */
    NULL,       /* menu_settings */
    0,
};

NQR_EXPORT const nqr_renderer* nqr_get_renderer(uint32_t engine_abi_version,
                                                const nqr_engine* engine) {
    if (NQR_ABI_MAJOR(engine_abi_version) != NQR_ABI_VERSION_MAJOR || !engine ||
        engine->size < sizeof(nqr_engine)) {
        return 0;
    }
    return &g_table;
}

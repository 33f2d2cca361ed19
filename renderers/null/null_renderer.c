/* The null renderer: every draw hook is present and does nothing, so the engine draws nothing
 * (a NULL hook would make the engine draw that part with its defaults). It touches no GL, which
 * makes it the renderer for engine tests, for timing the engine without drawing, and the
 * smallest example of the plugin ABI — written in C to show the boundary needs no C++. Its
 * state lives in its instance (init returns it, every hook gets it back as `self`). */
#include <stdlib.h>

#include "nqr_renderer.h"

typedef struct null_renderer {
    const nqr_engine* engine;
    unsigned models;
} null_renderer;

static void* null_init(const nqr_engine* engine) {
    null_renderer* self = (null_renderer*)calloc(1, sizeof(null_renderer));
    if (!self) return NULL;
    self->engine = engine;
    engine->log(engine->context, NQR_LOG_INFO, "null renderer: nothing will be drawn");
    return self;
}

static void null_shutdown(void* self) { free(self); }
static void null_register_model(void* self, const nqr_model* model) {
    (void)model;
    ++((null_renderer*)self)->models;
}
static void null_release_model(void* self, nqr_model_id id) {
    (void)id;
    --((null_renderer*)self)->models;
}
static void null_frame(void* self, const nqr_frame* frame) {
    (void)self;
    (void)frame;
}
static void null_post(void* self, const nqr_frame* frame, const nqr_gbuffer* g) {
    (void)self;
    (void)frame;
    (void)g;
}

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

/* A renderer plugin written and built for ABI 1.5 — against the 1.5 header kept beside it
 * (abi_1_5/nqr_renderer.h, a copy of engine/abi/nqr_renderer.h as 1.5 left it) — which the 2.0
 * engine must still load and run. It uses what a 1.x plugin had: services without a context
 * (log, a cvar, a console command, GL through the proc-address service) and the 1.x frame, with
 * the camera and each entity's light held by value.
 *
 * It draws, through GL's scissored clears only: the world as one flat colour (kWorld), and at
 * each alias entity in view a square of `legacy15_marker` pixels centred where the 1.x camera's
 * view_projection puts the entity's origin, its red channel 255 and its green the entity's
 * ambient light (x 100, clamped). Its command `legacy15_report` logs the camera and the alias
 * entities of the last frame, so a test can check the squares against its own projection. */
#include <stdio.h>
#include <string.h>

#include "abi_1_5/nqr_renderer.h"

typedef void (*clear_color_fn)(float, float, float, float);
typedef void (*clear_fn)(unsigned);
typedef void (*enable_fn)(unsigned);
typedef void (*scissor_fn)(int, int, int, int);

#define GL_COLOR_BUFFER_BIT 0x4000u
#define GL_SCISSOR_TEST 0x0C11u
#define MAX_SEEN 64

static const nqr_engine* g_engine;
static const nqr_cvar* g_marker;
static clear_color_fn g_clear_color;
static clear_fn g_clear;
static enable_fn g_enable, g_disable;
static scissor_fn g_scissor;

/* The last frame, for the report. */
static nqr_camera g_camera;
static unsigned g_num_seen;
static float g_seen_origin[MAX_SEEN][3];
static float g_seen_ambient[MAX_SEEN];
static unsigned g_seen_lights[MAX_SEEN];

/* The 1.5 layout as this plugin was compiled, for the engine's layout test. */
NQR_EXPORT void nqr_legacy_layout(size_t out[8]) {
    out[0] = sizeof(nqr_frame);
    out[1] = offsetof(nqr_frame, camera);
    out[2] = offsetof(nqr_frame, view_planes);
    out[3] = sizeof(nqr_entity);
    out[4] = offsetof(nqr_entity, light);
    out[5] = sizeof(nqr_entity_light);
    out[6] = sizeof(nqr_engine);
    out[7] = sizeof(nqr_renderer);
}

static void report(void* user, int argc, const char* const* argv) {
    char line[256];
    unsigned i;
    (void)user;
    (void)argc;
    (void)argv;
    snprintf(line, sizeof line, "legacy15 camera %.3f %.3f %.3f angles %.3f %.3f %.3f fov %.3f %d %d",
             g_camera.origin[0], g_camera.origin[1], g_camera.origin[2], g_camera.angles[0],
             g_camera.angles[1], g_camera.angles[2], g_camera.fov_x, g_camera.viewport[2],
             g_camera.viewport[3]);
    g_engine->log(NQR_LOG_INFO, line);
    for (i = 0; i < g_num_seen; ++i) {
        snprintf(line, sizeof line, "legacy15 entity %.3f %.3f %.3f ambient %.3f lights %u",
                 g_seen_origin[i][0], g_seen_origin[i][1], g_seen_origin[i][2], g_seen_ambient[i],
                 g_seen_lights[i]);
        g_engine->log(NQR_LOG_INFO, line);
    }
}

static int legacy_init(const nqr_engine* engine) {
    g_engine = engine;
    g_clear_color = (clear_color_fn)engine->gl_get_proc_address("glClearColor");
    g_clear = (clear_fn)engine->gl_get_proc_address("glClear");
    g_enable = (enable_fn)engine->gl_get_proc_address("glEnable");
    g_disable = (enable_fn)engine->gl_get_proc_address("glDisable");
    g_scissor = (scissor_fn)engine->gl_get_proc_address("glScissor");
    if (!g_clear_color || !g_clear || !g_enable || !g_disable || !g_scissor) {
        engine->log(NQR_LOG_ERROR, "legacy15: no GL");
        return 1;
    }
    g_marker = engine->cvar_register("legacy15_marker", "6", 0, "marker size in pixels");
    engine->command_register("legacy15_report", report, 0, "logs the last frame");
    engine->log(NQR_LOG_INFO, "legacy15: a 1.5 plugin is running");
    return 0;
}

static void legacy_shutdown(void) { g_engine = 0; }

static void draw_world(const nqr_frame* f) {
    g_camera = f->camera;
    g_clear_color(0.0f, 0.25f, 0.75f, 1.0f); /* kWorld */
    g_clear(GL_COLOR_BUFFER_BIT);
}

static void draw_alias(const nqr_frame* f) {
    const int* vp = f->camera.viewport;
    const float* m = f->camera.view_projection;
    int size = g_marker && g_marker->integer > 0 ? g_marker->integer : 6;
    unsigned i;
    g_num_seen = 0;
    g_enable(GL_SCISSOR_TEST);
    for (i = 0; i < f->num_alias_entities; ++i) {
        const nqr_entity* e = f->alias_entities[i];
        const float* o = e->origin;
        float x, y, w, ambient;
        if (e->flags & (NQR_ENTITY_OUTSIDE_VIEW | NQR_ENTITY_VIEWMODEL)) continue;
        w = m[3] * o[0] + m[7] * o[1] + m[11] * o[2] + m[15];
        if (w <= 0.0f) continue;
        x = (m[0] * o[0] + m[4] * o[1] + m[8] * o[2] + m[12]) / w;
        y = (m[1] * o[0] + m[5] * o[1] + m[9] * o[2] + m[13]) / w;
        ambient = e->light.ambient * 100.0f / 255.0f;
        if (g_num_seen < MAX_SEEN) {
            memcpy(g_seen_origin[g_num_seen], o, sizeof(float) * 3);
            g_seen_ambient[g_num_seen] = e->light.ambient;
            g_seen_lights[g_num_seen] = e->light.num_lights;
            ++g_num_seen;
        }
        g_scissor(vp[0] + (int)((x * 0.5f + 0.5f) * vp[2]) - size / 2,
                  vp[1] + (int)((y * 0.5f + 0.5f) * vp[3]) - size / 2, size, size);
        g_clear_color(1.0f, ambient > 1.0f ? 1.0f : ambient, 0.0f, 1.0f);
        g_clear(GL_COLOR_BUFFER_BIT);
    }
    g_disable(GL_SCISSOR_TEST);
}

static void draw_nothing(const nqr_frame* f) { (void)f; }
static void model_nothing(const nqr_model* m) { (void)m; }
static void release_nothing(nqr_model_id id) { (void)id; }

static const nqr_renderer g_table = {
    sizeof(nqr_renderer), NQR_ABI_VERSION, "legacy15", "an ABI 1.5 plugin (engine tests)", 0,
    legacy_init, legacy_shutdown, model_nothing, release_nothing,
    0,            /* begin_frame */
    draw_world, draw_nothing, draw_alias, draw_nothing, draw_nothing,
    0, 0,         /* post_process, end_frame */
    0, 0,         /* menu_settings */
};

NQR_EXPORT const nqr_renderer* nqr_get_renderer(uint32_t engine_abi_version,
                                                const nqr_engine* engine) {
    if (NQR_ABI_MAJOR(engine_abi_version) != NQR_ABI_VERSION_MAJOR || !engine ||
        engine->size < sizeof(nqr_engine)) {
        return 0;
    }
    return &g_table;
}

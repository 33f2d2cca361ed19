/* Renderer plugins that misbehave on purpose, for the plugin-host tests. One source, built
 * several times with a different TEST_PLUGIN_KIND each (see tests/plugins/CMakeLists.txt). */
#include <stdlib.h>

#include "nqr_renderer.h"

#define KIND_PROBE 0    /* well-behaved; counts every call */
#define KIND_BADABI 1   /* claims ABI major 3 */
#define KIND_REFUSE 2   /* entry point returns NULL */
#define KIND_FAILINIT 3 /* registers a command, then init fails */
#define KIND_SMALL 4    /* function table smaller than ABI 2.0's */
#define KIND_NOENTRY 5  /* no entry point at all */
#define KIND_POST 6     /* wants the G-buffer; post_process shows the normals buffer */

/* Counters a test reads back through nqr_test_counters(). */
typedef struct probe_counters {
    int inits, shutdowns, models_registered, models_released, frames;
    const nqr_cvar* cvar;
} probe_counters;

/* The counters are the library's, read by tests; each instance holds only its services. */
static probe_counters g_counters;

NQR_EXPORT probe_counters* nqr_test_counters(void) { return &g_counters; }

typedef struct probe {
    const nqr_engine* engine;
} probe;

static void probe_command(void* user, int argc, const char* const* argv) {
    const nqr_engine* engine = ((probe*)user)->engine;
    (void)argc;
    (void)argv;
    engine->log(engine->context, NQR_LOG_INFO, "probe command ran");
}

static void* probe_init(const nqr_engine* engine) {
    probe* self = (probe*)calloc(1, sizeof(probe));
    self->engine = engine;
    ++g_counters.inits;
    g_counters.cvar =
        engine->cvar_register(engine->context, "probe_value", "7", NQR_CVAR_ARCHIVE, "test cvar");
    engine->command_register(engine->context, "probe_cmd", probe_command, self, "test command");
    if (TEST_PLUGIN_KIND == KIND_FAILINIT) {
        free(self);
        return NULL;
    }
    return self;
}

static void probe_shutdown(void* self) {
    ++g_counters.shutdowns;
    free(self);
}
static void probe_register(void* self, const nqr_model* m) {
    (void)self;
    (void)m;
    ++g_counters.models_registered;
}
static void probe_release(void* self, nqr_model_id id) {
    (void)self;
    (void)id;
    ++g_counters.models_released;
}
static void probe_frame(void* self, const nqr_frame* f) {
    (void)self;
    (void)f;
    ++g_counters.frames;
}

/* KIND_POST: copies the scene's normal buffer to the screen, so a test can see what the
 * engine put there. GL is reached through the engine's proc-address service: plugins need no
 * GL loader of their own. */
typedef void (*bind_fb_fn)(unsigned, unsigned);
typedef void (*read_buffer_fn)(unsigned);
typedef void (*blit_fn)(int, int, int, int, int, int, int, int, unsigned, unsigned);

static void probe_post(void* self, const nqr_frame* f, const nqr_gbuffer* g) {
    const nqr_engine* e = ((probe*)self)->engine;
    bind_fb_fn bind = (bind_fb_fn)e->gl_get_proc_address(e->context, "glBindFramebuffer");
    read_buffer_fn read = (read_buffer_fn)e->gl_get_proc_address(e->context, "glReadBuffer");
    blit_fn blit = (blit_fn)e->gl_get_proc_address(e->context, "glBlitFramebuffer");
    (void)f;
    if (!bind || !read || !blit) return;
    bind(0x8CA8 /* GL_READ_FRAMEBUFFER */, g->framebuffer);
    read(0x8CE1 /* GL_COLOR_ATTACHMENT1 */);
    blit(0, 0, g->width, g->height, 0, 0, g->width, g->height, 0x4000 /* COLOR_BIT */,
         0x2600 /* GL_NEAREST */);
    read(0x8CE0 /* GL_COLOR_ATTACHMENT0 */);
    bind(0x8CA8, 0);
}

static nqr_renderer g_table = {
    sizeof(nqr_renderer), NQR_ABI_VERSION, "probe", "test plugin", 0,
    probe_init, probe_shutdown, probe_register, probe_release,
    probe_frame, 0, 0, 0, 0, 0, 0, 0,
    0, 0, /* menu_settings, num_menu_settings */
};

/* KIND_NOENTRY exports its table under a misspelled name, so the engine finds no entry point. */
#if TEST_PLUGIN_KIND == KIND_NOENTRY
#define ENTRY_NAME nqr_get_renderer_misspelled
#else
#define ENTRY_NAME nqr_get_renderer
#endif

NQR_EXPORT const nqr_renderer* ENTRY_NAME(uint32_t version, const nqr_engine* engine) {
    (void)version;
    (void)engine;
    if (TEST_PLUGIN_KIND == KIND_REFUSE) return 0;
    if (TEST_PLUGIN_KIND == KIND_BADABI) g_table.abi_version = 3u << 16;
    if (TEST_PLUGIN_KIND == KIND_SMALL) g_table.size = 16;
    if (TEST_PLUGIN_KIND == KIND_POST) {
        g_table.wants = NQR_WANTS_GBUFFER;
        g_table.post_process = probe_post;
        g_table.begin_frame = 0;
    }
    return &g_table;
}

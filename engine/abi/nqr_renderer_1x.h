/* nqr_renderer_1x.h — the 1.x layouts of the structs ABI 2.0 changed, frozen as 1.5 left them,
 * for the engine's loader of 1.x plugins (engine/plugin/legacy_renderer). Not for plugins: a
 * 1.x plugin was built from the 1.x nqr_renderer.h (tests/plugins/abi_1_5/ keeps a copy, and a
 * test checks these layouts against it).
 *
 * What changed in 2.0: the services and hooks gained a context argument (1.x has none), the
 * camera and the entity's light are reached through pointers (1.x embeds them by value, so
 * neither could grow), and nqr_frame.blend went. Every other struct is the same in both and is
 * shared from nqr_renderer.h: 2.x only appends to them, which 1.x readers skip by size. */
#ifndef NQR_RENDERER_1X_H
#define NQR_RENDERER_1X_H

#include "nqr_renderer.h"

#ifdef __cplusplus
extern "C" {
#endif

#define NQR1_ABI_VERSION ((1u << 16) | 5u)

typedef struct nqr1_engine {
    uint32_t size;
    uint32_t abi_version;
    void (*log)(int level, const char* text);
    const nqr_cvar* (*cvar_register)(const char* name, const char* default_value, uint32_t flags,
                                     const char* description);
    void (*cvar_set)(const char* name, const char* value);
    int (*command_register)(const char* name, nqr_command_fn fn, void* user,
                            const char* description);
    int (*file_read)(const char* path, nqr_blob* out);
    void (*file_free)(nqr_blob* blob);
    void* (*gl_get_proc_address)(const char* name);
    double (*real_time)(void);
    void (*trace)(const float start[3], const float end[3], nqr_trace* out);
    const uint8_t* palette;
    const uint8_t* colormap;
    void (*gpu_pass_begin)(const char* pass_name);
    void (*gpu_pass_end)(void);
} nqr1_engine;

typedef struct nqr1_camera {
    uint32_t size;
    float origin[3];
    float angles[3];
    float forward[3], right[3], up[3];
    float view[16];
    float projection[16];
    float view_projection[16];
    float fov_x, fov_y;
    float z_near, z_far;
    int32_t viewport[4];
} nqr1_camera;

typedef struct nqr1_light_source {
    uint32_t size;
    float position[3];
    float color[3];
} nqr1_light_source;

typedef struct nqr1_entity_light {
    uint32_t size;
    float ambient;
    float directional;
    float direction[3];
    float color[3];
    float ambient_cube[6][3];
    uint32_t num_lights;
    nqr1_light_source lights[4];
} nqr1_entity_light;

typedef struct nqr1_entity {
    uint32_t size;
    uint32_t number;
    nqr_model_id model;
    uint32_t flags;
    float origin[3], angles[3];
    float scale;
    float model_matrix[16];
    float eye_model[3];
    uint32_t frame;
    uint32_t pose0, pose1;
    float lerp;
    uint32_t skin_image;
    uint32_t skin;
    uint8_t top_color, bottom_color;
    uint8_t has_translation;
    uint8_t pad0;
    float alpha;
    uint32_t effects;
    nqr1_entity_light light;
} nqr1_entity;

typedef struct nqr1_frame {
    uint32_t size;
    uint64_t number;
    double time;
    double real_time;
    float frame_time;
    uint32_t flags;
    nqr1_camera camera;
    nqr_model_id world;
    const uint32_t* visible_surfaces;
    uint32_t num_visible_surfaces;
    const float* lightstyles;
    const nqr1_entity* const* brush_entities;
    uint32_t num_brush_entities;
    const nqr1_entity* const* alias_entities;
    uint32_t num_alias_entities;
    const nqr1_entity* const* sprite_entities;
    uint32_t num_sprite_entities;
    const nqr_dlight* dlights;
    uint32_t num_dlights;
    const nqr_particle* particles;
    uint32_t num_particles;
    float blend[4];
    float view_planes[4][4];
} nqr1_frame;

typedef struct nqr1_renderer {
    uint32_t size;
    uint32_t abi_version;
    const char* name;
    const char* description;
    uint32_t wants;
    int (*init)(const nqr1_engine* engine);
    void (*shutdown)(void);
    void (*register_model)(const nqr_model* model);
    void (*release_model)(nqr_model_id id);
    void (*begin_frame)(const nqr1_frame* frame);
    void (*draw_world)(const nqr1_frame* frame);
    void (*draw_brush_entities)(const nqr1_frame* frame);
    void (*draw_alias_entities)(const nqr1_frame* frame);
    void (*draw_sprite_entities)(const nqr1_frame* frame);
    void (*draw_particles)(const nqr1_frame* frame);
    void (*post_process)(const nqr1_frame* frame, const nqr_gbuffer* gbuffer);
    void (*end_frame)(const nqr1_frame* frame);
    const nqr_menu_setting* menu_settings;
    uint32_t num_menu_settings;
} nqr1_renderer;

typedef const nqr1_renderer* (*nqr1_get_renderer_fn)(uint32_t engine_abi_version,
                                                     const nqr1_engine* engine);

#ifdef __cplusplus
}
#endif

#endif /* NQR_RENDERER_1X_H */

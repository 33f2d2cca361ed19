/* ABI 1.5 as it was released: a copy kept for the 1.x compatibility tests (tests/plugins/
 * legacy_1_5_plugin.c is built from it). Do not edit: engine/abi/nqr_renderer.h is the live ABI. */
/* nqr_renderer.h — the engine <-> renderer-plugin boundary of NPRQuake (the only header a
 * plugin needs from the engine). Pure C: POD structs and function tables, no C++ types.
 *
 * VERSIONING
 *   Every struct starts with `uint32_t size`, set by whoever fills it to sizeof() as it was
 *   compiled. Arrays of structs are walked with that size as the stride (nqr_at() below), so a
 *   newer side may append fields at the end and an older side still reads the prefix it knows.
 *   NQR_ABI_VERSION = major << 16 | minor. A different major is refused by both sides; a newer
 *   minor only appends. The engine re-checks the version and every size it is handed.
 *
 * ENTRY POINT
 *   A plugin is a shared library (nqr_<name>.so in the plugins directory) exporting
 *       const nqr_renderer* nqr_get_renderer(uint32_t engine_abi_version, const nqr_engine* engine);
 *   It returns its function table, or NULL to refuse (e.g. an unknown major version). Nothing
 *   may touch GL before init().
 *
 * OPTIONAL HOOKS
 *   Every draw hook may be NULL: the engine then draws that part with the shared default code
 *   (nprlib's classic GLQuake drawers), so a style can replace only alias-model drawing, as the
 *   NPRQuake styles did. init/shutdown are required.
 *
 * COORDINATES (see docs/coordinates.md)
 *   All positions are Quake world space: right-handed, +X forward at yaw 0, +Y left, +Z up,
 *   angles in degrees as (pitch, yaw, roll). The view matrix already contains the Quake -> GL
 *   axis change (Quake +X forward -> GL -Z, +Y left -> GL -X, +Z up -> GL +Y), so
 *   projection * view * model maps model-space positions straight to clip space.
 *   Matrices are column-major float[16], as glUniformMatrix4fv(loc, 1, GL_FALSE, m) expects.
 *
 * LIFETIME AND THREADING
 *   Everything is called on the thread that owns the GL context, with it current. Model data
 *   stays valid from register_model until release_model (or shutdown); frame data only for the
 *   duration of the call. A plugin copies what it keeps. Plugins must not allocate per frame in
 *   steady state (the engine does not either).
 */
#ifndef NQR_RENDERER_H
#define NQR_RENDERER_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define NQR_ABI_VERSION_MAJOR 1u
#define NQR_ABI_VERSION_MINOR 5u
#define NQR_ABI_VERSION ((NQR_ABI_VERSION_MAJOR << 16) | NQR_ABI_VERSION_MINOR)
#define NQR_ABI_MAJOR(v) ((uint32_t)(v) >> 16)
#define NQR_ENTRY_POINT "nqr_get_renderer"

#if defined(_WIN32)
#define NQR_EXPORT __declspec(dllexport)
#else
#define NQR_EXPORT __attribute__((visibility("default")))
#endif

/* Element i of an array of size-prefixed structs whose first element gives the stride. */
#define nqr_at(type, array, i) \
    ((const type*)((const unsigned char*)(array) + (size_t)(i) * (array)->size))

/* ======================================================================= engine services */

enum nqr_log_level { NQR_LOG_INFO = 0, NQR_LOG_WARNING = 1, NQR_LOG_ERROR = 2, NQR_LOG_DEBUG = 3 };

enum nqr_cvar_flags {
    NQR_CVAR_ARCHIVE = 1u << 0, /* saved to config.cfg */
    NQR_CVAR_READONLY = 1u << 1
};

/* A cvar's live value. The pointer cvar_register returns stays valid for the engine's whole
 * lifetime, also after the plugin that registered it is unloaded; `string` is valid until the
 * cvar's next change. Poll modified_count to notice changes cheaply. */
typedef struct nqr_cvar {
    uint32_t size;
    float value;
    int32_t integer;
    const char* string;
    uint32_t modified_count;
} nqr_cvar;

typedef struct nqr_blob {
    uint32_t size;
    const uint8_t* data;
    size_t length;
    void* engine_private;
} nqr_blob;

typedef void (*nqr_command_fn)(void* user, int argc, const char* const* argv);

/* A line segment traced against the world's hull 0 (point-sized). */
typedef struct nqr_trace {
    uint32_t size;
    float fraction; /* 0..1 along the segment; 1 = nothing hit */
    float end[3];
    float plane_normal[3]; /* of the surface hit */
    float plane_dist;
    int32_t start_solid;
} nqr_trace;

typedef struct nqr_engine {
    uint32_t size;
    uint32_t abi_version;

    void (*log)(int level, const char* text);

    /* Registered cvars and commands belong to the calling plugin: on unload its commands are
     * removed and its cvars stay, with their values, for the next plugin that registers them. */
    const nqr_cvar* (*cvar_register)(const char* name, const char* default_value, uint32_t flags,
                                     const char* description);
    void (*cvar_set)(const char* name, const char* value);
    int (*command_register)(const char* name, nqr_command_fn fn, void* user,
                            const char* description);

    /* Reads a file through the virtual filesystem (game dirs, paks). 0 on success; hand the
     * blob back with file_free. */
    int (*file_read)(const char* path, nqr_blob* out);
    void (*file_free)(nqr_blob* blob);

    void* (*gl_get_proc_address)(const char* name);
    double (*real_time)(void); /* monotonic seconds */

    /* World queries, valid while a map is loaded (they return fraction 1 / 0 otherwise). */
    void (*trace)(const float start[3], const float end[3], nqr_trace* out);

    /* Quake palette (256 RGB triples) and colormap (64 light rows x 256, then 256 more bytes). */
    const uint8_t* palette;
    const uint8_t* colormap;

    /* GPU timing: wrap a plugin's own passes; reported by timedemo and -benchjson. */
    void (*gpu_pass_begin)(const char* pass_name);
    void (*gpu_pass_end)(void);
} nqr_engine;

/* ======================================================================= models */

typedef uint32_t nqr_model_id; /* 0 = none */

enum nqr_model_kind { NQR_MODEL_BRUSH = 1, NQR_MODEL_ALIAS = 2, NQR_MODEL_SPRITE = 3 };

/* ---- brush models (BSP): the world, its inline submodels "*N", and b_*.bsp item boxes */

enum nqr_texture_flags {
    NQR_TEXTURE_SKY = 1u << 0,    /* "sky*": two scrolling layers, left half front */
    NQR_TEXTURE_LIQUID = 1u << 1, /* "*water", "*lava", "*slime", "*tele": warped, unlit */
    NQR_TEXTURE_MISSING = 1u << 2 /* placeholder for a texture the map did not carry */
};

typedef struct nqr_texture {
    uint32_t size;
    const char* name;
    uint32_t width, height;
    const uint8_t* mips[4]; /* palette indices, (width >> i) x (height >> i) */
    uint32_t flags;
    /* Animation chains ("+0name".."+9name" and alternates "+aname".."+jname"): indices of
     * this texture's frames, in order, or num_anim_frames = 0 when not animated. Frames
     * advance every 0.2 s; brush entities with frame != 0 use the alternate chain. */
    uint32_t num_anim_frames, num_alt_anim_frames;
    int32_t anim_frames[10];
    int32_t alt_anim_frames[10];
} nqr_texture;

enum nqr_surface_flags {
    NQR_SURFACE_SKY = 1u << 0,
    NQR_SURFACE_LIQUID = 1u << 1,
    NQR_SURFACE_PLANE_BACK = 1u << 2 /* the face uses the back side of its BSP plane */
};

/* One BSP face: a convex polygon, its vertices counter-clockwise seen from the front (the side
 * `normal` points to), GL's default front face. (Quake's files store them clockwise; the
 * engine reverses them.) */
typedef struct nqr_surface {
    uint32_t size;
    uint32_t first_vertex, num_vertices; /* range in nqr_brush_model.positions / vertex_ids */
    float normal[3];                     /* facing out of the front side */
    float dist;
    float tex_s[4], tex_t[4]; /* texel s = dot(pos, tex_s.xyz) + tex_s[3]; same for t */
    int32_t texture;          /* index into textures, -1 = none */
    uint32_t flags;
    uint8_t styles[4];      /* light styles, 255 = unused */
    int32_t light_offset;   /* first lightmap sample in lighting_rgb (x3 bytes), -1 = none */
    int32_t texture_mins[2];
    int32_t extents[2]; /* lightmap is (extents >> 4) + 1 samples in each direction */
} nqr_surface;

typedef struct nqr_brush_model {
    uint32_t size;
    uint32_t num_surfaces;
    const nqr_surface* surfaces;
    uint32_t num_vertices;
    const float* positions;       /* num_vertices x 3 */
    const uint32_t* vertex_ids;   /* BSP vertex index of each polygon vertex: shared ids give
                                     the mesh's adjacency (edges between faces) */
    uint32_t num_textures;
    const nqr_texture* textures;
    const uint8_t* lighting_rgb; /* RGB lightmap samples (.lit, or grey expanded), may be NULL */
    size_t num_light_samples;
} nqr_brush_model;

/* ---- alias models (MDL): every pose decoded; skins as 8-bit palette indices */

typedef struct nqr_alias_vertex {
    uint8_t v[3];         /* packed position: model = scale * v + origin */
    uint8_t normal_index; /* into Quake's table of 162 normals (nprlib has it) */
} nqr_alias_vertex;

typedef struct nqr_alias_frame {
    uint32_t size;
    const char* name;
    uint32_t first_pose, num_poses; /* num_poses > 1: a frame group */
    const float* intervals;         /* num_poses end times within the group's cycle, seconds */
} nqr_alias_frame;

typedef struct nqr_alias_skin {
    uint32_t size;
    uint32_t num_images;          /* > 1: a skin group */
    const uint8_t* const* images; /* each skin_width x skin_height palette indices */
    const float* intervals;
} nqr_alias_skin;

typedef struct nqr_alias_model {
    uint32_t size;
    float scale[3], origin[3];
    int32_t skin_width, skin_height;
    uint32_t num_vertices, num_triangles, num_poses, num_frames, num_skins;
    uint32_t flags;                 /* MDL flags: EF_ROCKET 1, EF_GRENADE 2, EF_GIB 4, ... */
    const int32_t* st;              /* num_vertices x 3: onseam, s, t */
    const int32_t* triangles;       /* num_triangles x 4: facesfront, v0, v1, v2 */
    const nqr_alias_vertex* poses;  /* num_poses x num_vertices */
    const nqr_alias_frame* frames;  /* num_frames */
    const nqr_alias_skin* skins;    /* num_skins */
} nqr_alias_model;

/* ---- sprites (SPR) */

typedef struct nqr_sprite_image {
    uint32_t size;
    int32_t width, height;
    int32_t origin_x, origin_y; /* offset of the image's top-left from the entity origin */
    const uint8_t* pixels;      /* palette indices; 255 is transparent */
} nqr_sprite_image;

typedef struct nqr_sprite_frame {
    uint32_t size;
    uint32_t first_image, num_images; /* num_images > 1: a frame group */
    const float* intervals;
} nqr_sprite_frame;

typedef struct nqr_sprite_model {
    uint32_t size;
    uint32_t type; /* 0 parallel upright, 1 facing upright, 2 parallel, 3 oriented,
                      4 parallel oriented */
    uint32_t num_images, num_frames;
    const nqr_sprite_image* images;
    const nqr_sprite_frame* frames;
} nqr_sprite_model;

typedef struct nqr_model {
    uint32_t size;
    nqr_model_id id;
    uint32_t kind; /* nqr_model_kind */
    const char* name;
    float mins[3], maxs[3];
    float radius;
    /* Brush: the world and its inline submodels ("*N") share one nqr_brush_model; this model
     * is the range [first_surface, first_surface + num_surfaces) of it. */
    const nqr_brush_model* brush;
    uint32_t first_surface, num_surfaces;
    const nqr_alias_model* alias;
    const nqr_sprite_model* sprite;
} nqr_model;

/* ======================================================================= a frame */

typedef struct nqr_camera {
    uint32_t size;
    float origin[3]; /* the eye, Quake world space */
    float angles[3]; /* pitch, yaw, roll in degrees */
    float forward[3], right[3], up[3];
    float view[16];
    float projection[16];
    float view_projection[16];
    float fov_x, fov_y; /* degrees */
    float z_near, z_far;
    int32_t viewport[4]; /* x, y, width, height in pixels (GL: origin bottom-left) */
} nqr_camera;

#define NQR_MAX_ENTITY_LIGHTS 4

/* Since 1.4. One local light that matters for an entity (map light entity or dynamic light). */
typedef struct nqr_light_source {
    uint32_t size;
    float position[3]; /* world */
    float color[3];    /* RGB light arriving at the entity's origin, ambient's scale (1 = lightmap
                          128): Quake's linear falloff, line of sight and the fade weight applied */
} nqr_light_source;

/* What lights an entity, sampled by the engine from the map at the entity's origin. */
typedef struct nqr_entity_light {
    uint32_t size;
    float ambient;      /* GLQuake's shade light, 0..~2 (1 = normal) */
    float directional;  /* strength of the dominant light, same scale */
    float direction[3]; /* unit vector in world space pointing from the entity toward it */
    float color[3];     /* tint of the lightmap under the entity (1,1,1 for white light) */
    /* Irradiance arriving from +X, -X, +Y, -Y, +Z, -Z (world), RGB, ambient's scale: Valve's
     * ambient cube. Since 1.4 baked at level load from the light the map's surfaces send back
     * (lightmap times texture colour, sky, cosine-weighted over 162 directions per sample
     * point, light styles at normal), blended between nearby samples, plus dynamic lights. */
    float ambient_cube[6][3];
    /* Since 1.4: the strongest lights at the entity, strongest first; each fades in and out
     * over time, so nothing pops as lights enter or leave the set. Walk the array with nqr_at
     * (stride lights[0].size), and only when this struct's size covers it. */
    uint32_t num_lights;
    nqr_light_source lights[NQR_MAX_ENTITY_LIGHTS];
} nqr_entity_light;

enum nqr_entity_flags {
    NQR_ENTITY_VIEWMODEL = 1u << 0, /* the player's weapon: drawn last, depth range hack */
    NQR_ENTITY_STATIC = 1u << 1,    /* from svc_spawnstatic */
    NQR_ENTITY_TEMP = 1u << 2,      /* beams, explosions added by the client */
    NQR_ENTITY_FULLBRIGHT = 1u << 3, /* ignore lighting (EF_BRIGHTFIELD, muzzle flash…) */
    /* Since 1.1: in the PVS but its bounding sphere, or for an alias model the box of this
     * frame's two poses (since 1.2 also its blended vertices), is outside the view frustum, so
     * nothing of the model itself is on screen. Listed anyway for effects that reach into the view (shadows, reflections);
     * drawers of the model skip it (nprlib's drawers do). */
    NQR_ENTITY_OUTSIDE_VIEW = 1u << 4,
    /* Since 1.2: inside the frustum, but at every pixel centre of the camera's viewport it
     * could cover, one of the frame's visible world surfaces (an opaque one: not sky, liquid or
     * fence) lies nearer than any part of the model, so once those are drawn with depth writes
     * the depth test rejects all of its fragments. Listed, like OUTSIDE_VIEW, for effects that
     * reach past the model (shadows); drawers that draw the world that way skip it (nprlib's
     * drawers do); one that draws the world see-through or at another resolution must not. */
    NQR_ENTITY_OCCLUDED = 1u << 5
};

typedef struct nqr_entity {
    uint32_t size;
    uint32_t number; /* server entity number (0 = world, static/temp ones numbered after) */
    nqr_model_id model;
    uint32_t flags;
    float origin[3], angles[3];
    float scale;
    float model_matrix[16]; /* model -> world */
    float eye_model[3];     /* the camera origin in this entity's model space */
    /* Animation, resolved by the engine (frame groups included): draw the blend of two poses
     * (alias) or images (sprite): pose0 * (1 - lerp) + pose1 * lerp. */
    uint32_t frame;
    uint32_t pose0, pose1;
    float lerp;
    uint32_t skin_image; /* alias: index of the image within the current skin (groups resolved) */
    uint32_t skin;
    uint8_t top_color, bottom_color; /* player colours 0..13 for shirt/pants translation */
    uint8_t has_translation;         /* colours apply (player models) */
    uint8_t pad0;
    float alpha; /* 1 = opaque */
    uint32_t effects;
    nqr_entity_light light;
} nqr_entity;

typedef struct nqr_dlight {
    uint32_t size;
    float origin[3];
    float radius;
    float color[3];
} nqr_dlight;

typedef struct nqr_particle {
    uint32_t size;
    float origin[3];
    uint8_t color; /* palette index */
    uint8_t pad[3];
    float alpha;
} nqr_particle;

/* Colour, depth and normals of the rendered scene, for post-processing plugins. GL texture
 * names of the engine's scene framebuffer; normals are view-space, encoded n * 0.5 + 0.5.
 * The normal's alpha is the share of the pixel's colour that ambient obscurance darkens: 1 for
 * all of it, 0 for what is not solid (sky, liquids); since 1.5 a style that keeps ambient light
 * apart writes ambient / total there (by luminance), so obscurance shades only that part. */
typedef struct nqr_gbuffer {
    uint32_t size;
    uint32_t framebuffer;
    uint32_t color_texture;  /* RGBA8 */
    uint32_t depth_texture;  /* DEPTH24 (or DEPTH32F) */
    uint32_t normal_texture; /* RGBA8 or RGB10_A2 */
    int32_t width, height;
} nqr_gbuffer;

enum nqr_frame_flags {
    NQR_FRAME_UNDERWATER = 1u << 0,
    NQR_FRAME_INTERMISSION = 1u << 1,
    NQR_FRAME_WRITE_NORMALS = 1u << 2 /* scene shaders also write normals to location 1 */
};

typedef struct nqr_frame {
    uint32_t size;
    uint64_t number;
    double time;      /* client (game) time in seconds: drives animation and lightstyles */
    double real_time; /* wall-clock seconds */
    float frame_time;
    uint32_t flags;
    nqr_camera camera;

    nqr_model_id world; /* 0 when no map is loaded (showroom without world) */
    /* World surfaces that survived PVS and frustum culling this frame, grouped by texture: the
     * groups in the order of their nearest surface, each front to back (BSP order), so drawing
     * them in order lets depth testing skip hidden shading. */
    const uint32_t* visible_surfaces;
    uint32_t num_visible_surfaces;
    /* Light style intensities, 64 entries, 1.0 = normal ('m'); lightmap samples of style s
     * are scaled by lightstyles[s]. */
    const float* lightstyles;

    /* Entities to draw, grouped by model kind (the view model is in alias_entities, flagged). */
    const nqr_entity* const* brush_entities;
    uint32_t num_brush_entities;
    const nqr_entity* const* alias_entities;
    uint32_t num_alias_entities;
    const nqr_entity* const* sprite_entities;
    uint32_t num_sprite_entities;

    const nqr_dlight* dlights; /* array; stride dlights->size */
    uint32_t num_dlights;
    const nqr_particle* particles; /* array; stride particles->size */
    uint32_t num_particles;

    float blend[4]; /* full-screen tint (damage, powerups, liquids), premultiplied by alpha */

    /* Since 1.1. The view frustum's side planes (left, right, bottom, top) in world space as
     * (nx, ny, nz, d), unit normals pointing inward: p is inside a plane when n.p >= d. (Quake
     * culls nothing by distance, so there are no near and far planes.) */
    float view_planes[4][4];
} nqr_frame;

/* ======================================================================= the plugin */

enum nqr_renderer_wants {
    /* Render the scene into an offscreen colour + depth + normal framebuffer and call
     * post_process with it (for screen-space effects such as obscurance or edge detection). */
    NQR_WANTS_GBUFFER = 1u << 0
};

/* Since 1.3. One line of the style's page in the engine's Options menu: a cvar the plugin
 * registered, shown with a label and changed with the arrow keys. */
enum nqr_menu_setting_kind {
    NQR_MENU_TOGGLE = 0, /* 0 / 1, shown as off / on */
    NQR_MENU_RANGE = 1,  /* a slider from min to max in steps of step */
    NQR_MENU_CHOICE = 2  /* whole values 0 .. num_choices - 1, shown by choices[value] */
};

typedef struct nqr_menu_setting {
    uint32_t size;
    const char* cvar;  /* the cvar's name */
    const char* label; /* short: the menu shows up to 20 characters */
    uint32_t kind;     /* nqr_menu_setting_kind */
    float min, max, step;
    const char* const* choices;
    uint32_t num_choices;
} nqr_menu_setting;

typedef struct nqr_renderer {
    uint32_t size;
    uint32_t abi_version;
    const char* name;        /* short name, e.g. "technical" */
    const char* description; /* one line for r_plugins */
    uint32_t wants;          /* nqr_renderer_wants */

    /* Required. init: GL is current; register cvars, build shaders. 0 = ready; otherwise log
     * why and return non-zero: the engine keeps the previous renderer. shutdown: release every
     * GL object and allocation; the library is unloaded right after. */
    int (*init)(const nqr_engine* engine);
    void (*shutdown)(void);

    /* Models: called for every loaded model after init and whenever a map loads models. */
    void (*register_model)(const nqr_model* model);
    void (*release_model)(nqr_model_id id);

    /* Per frame, in this order; any of these may be NULL. */
    void (*begin_frame)(const nqr_frame* frame);
    void (*draw_world)(const nqr_frame* frame);
    void (*draw_brush_entities)(const nqr_frame* frame);
    void (*draw_alias_entities)(const nqr_frame* frame);
    void (*draw_sprite_entities)(const nqr_frame* frame);
    void (*draw_particles)(const nqr_frame* frame);
    void (*post_process)(const nqr_frame* frame, const nqr_gbuffer* gbuffer);
    void (*end_frame)(const nqr_frame* frame);

    /* Since 1.3 (may be NULL / 0). The style's main settings, in the order the menu lists
     * them; the array and its strings stay valid while the library is loaded. */
    const nqr_menu_setting* menu_settings; /* array; stride menu_settings->size */
    uint32_t num_menu_settings;
} nqr_renderer;

typedef const nqr_renderer* (*nqr_get_renderer_fn)(uint32_t engine_abi_version,
                                                   const nqr_engine* engine);

#ifdef __cplusplus
}
#endif

#endif /* NQR_RENDERER_H */

#include "plugin/legacy_renderer.h"

#include <algorithm>
#include <cstddef>
#include <cstring>

#include "plugin/table_checks.h"

namespace nq {

namespace {

// What 1.x and 2.0 share byte for byte: an entity up to `effects` (2.0 then points to its
// light), a light up to its list, the camera, and a frame's fields up to the camera.
// 1.x services have no context, so the one global of the engine's plugin side lives here.
constexpr size_t kSharedEntityBytes = offsetof(nqr1_entity, effects) + sizeof(uint32_t);
static_assert(offsetof(nqr1_entity, effects) == offsetof(nqr_entity, effects));
static_assert(offsetof(nqr1_entity_light, num_lights) == offsetof(nqr_entity_light, num_lights));
static_assert(sizeof(nqr1_camera) == sizeof(nqr_camera));
static_assert(sizeof(nqr1_light_source) == sizeof(nqr_light_source));
static_assert(offsetof(nqr1_frame, camera) == offsetof(nqr_frame, camera));

// The 1.x caller: set around each call into a 1.x plugin; between calls, the newest initialised.
const ServiceTable* g_caller = nullptr;
const ServiceTable* g_resting = nullptr;

const ServiceTable* caller() {
    return g_caller ? g_caller : g_resting;
}

const nqr_engine* current() {
    const ServiceTable* c = caller();
    return c ? &c->table() : nullptr;
}

void v1_log(int level, const char* text) {
    if (const nqr_engine* e = current()) e->log(e->context, level, text);
}
const nqr_cvar* v1_cvar_register(const char* name, const char* value, uint32_t flags,
                                 const char* description) {
    const nqr_engine* e = current();
    return e ? e->cvar_register(e->context, name, value, flags, description) : nullptr;
}
void v1_cvar_set(const char* name, const char* value) {
    if (const nqr_engine* e = current()) e->cvar_set(e->context, name, value);
}
int v1_command_register(const char* name, nqr_command_fn fn, void* user, const char* description) {
    const nqr_engine* e = current();
    return e ? e->command_register(e->context, name, fn, user, description) : 0;
}
int v1_file_read(const char* path, nqr_blob* out) {
    const nqr_engine* e = current();
    return e ? e->file_read(e->context, path, out) : -1;
}
void v1_file_free(nqr_blob* blob) {
    if (const nqr_engine* e = current()) e->file_free(e->context, blob);
}
void* v1_gl_proc_address(const char* name) {
    const nqr_engine* e = current();
    return e ? e->gl_get_proc_address(e->context, name) : nullptr;
}
double v1_real_time() {
    const nqr_engine* e = current();
    return e ? e->real_time(e->context) : 0.0;
}
void v1_trace(const float start[3], const float end[3], nqr_trace* out) {
    if (const nqr_engine* e = current()) e->trace(e->context, start, end, out);
}
void v1_gpu_pass_begin(const char* name) {
    if (const nqr_engine* e = current()) e->gpu_pass_begin(e->context, name);
}
void v1_gpu_pass_end() {
    if (const nqr_engine* e = current()) e->gpu_pass_end(e->context);
}

// The smallest table a 1.x plugin can return: everything up to end_frame (ABI 1.0).
constexpr size_t kMinLegacySize = offsetof(nqr1_renderer, end_frame) + sizeof(void*);

void convert_light(const nqr_entity_light& in, nqr1_entity_light& out) {
    std::memcpy(&out, &in, offsetof(nqr1_entity_light, num_lights));
    out.size = sizeof(nqr1_entity_light);
    out.num_lights = 0;
    std::memset(out.lights, 0, sizeof out.lights);
    for (nqr1_light_source& s : out.lights) s.size = sizeof(nqr1_light_source);
    if (!in.lights) return;
    out.num_lights = std::min<uint32_t>(in.num_lights, NQR_MAX_ENTITY_LIGHTS);
    for (uint32_t i = 0; i < out.num_lights; ++i) {
        const nqr_light_source& s = *nqr_at(nqr_light_source, in.lights, i);
        std::memcpy(&out.lights[i], &s, std::min<size_t>(s.size, sizeof(nqr1_light_source)));
        out.lights[i].size = sizeof(nqr1_light_source);
    }
}

}  // namespace

nqr1_engine legacy_services(const ServiceTable& services) {
    const nqr_engine& t = services.table();
    return nqr1_engine{sizeof(nqr1_engine), NQR1_ABI_VERSION,    v1_log,         v1_cvar_register,
                       v1_cvar_set,         v1_command_register, v1_file_read,   v1_file_free,
                       v1_gl_proc_address,  v1_real_time,        v1_trace,       t.palette,
                       t.colormap,          v1_gpu_pass_begin,   v1_gpu_pass_end};
}

LegacyCallScope::LegacyCallScope(const ServiceTable* services) : saved_(g_caller) {
    g_caller = services;
}
LegacyCallScope::~LegacyCallScope() {
    g_caller = saved_;
}

std::string validate_legacy_table(const nqr1_renderer* table) {
    if (!table) return "the plugin refused to load (its entry point returned NULL)";
    if (NQR_ABI_MAJOR(table->abi_version) != 1) return "not a 1.x table";
    return check_table_basics(*table, kMinLegacySize);
}

template <auto Hook>
void LegacyRenderer::draw(void* self, const nqr_frame* frame) {
    auto* r = static_cast<LegacyRenderer*>(self);
    const nqr1_frame& converted = r->convert(*frame);
    LegacyCallScope scope(&r->services_);
    (r->legacy_.*Hook)(&converted);
}

void LegacyRenderer::post_process(void* self, const nqr_frame* frame, const nqr_gbuffer* g) {
    auto* r = static_cast<LegacyRenderer*>(self);
    const nqr1_frame& converted = r->convert(*frame);
    LegacyCallScope scope(&r->services_);
    r->legacy_.post_process(&converted, g);
}

LegacyRenderer::LegacyRenderer(const nqr1_renderer& table, const nqr1_engine& engine,
                               const ServiceTable& services)
    : engine_(engine), services_(services) {
    std::memcpy(&legacy_, &table, std::min<size_t>(table.size, sizeof(nqr1_renderer)));
    legacy_.size = sizeof(nqr1_renderer);
    using L = nqr1_renderer;
    auto hook = [](auto present, auto trampoline) { return present ? trampoline : nullptr; };
    table_ = nqr_renderer{
        .size = sizeof(nqr_renderer),
        .abi_version = legacy_.abi_version,
        .name = legacy_.name,
        .description = legacy_.description,
        .wants = legacy_.wants,
        .init = nullptr,  // init() below: the adapter exists before the plugin's instance
        .shutdown = [](void* self) { static_cast<LegacyRenderer*>(self)->call_shutdown(); },
        .register_model = hook(
            legacy_.register_model,
            +[](void* self, const nqr_model* m) {
                auto* r = static_cast<LegacyRenderer*>(self);
                LegacyCallScope scope(&r->services_);
                r->legacy_.register_model(m);
            }),
        .release_model = hook(
            legacy_.release_model,
            +[](void* self, nqr_model_id id) {
                auto* r = static_cast<LegacyRenderer*>(self);
                LegacyCallScope scope(&r->services_);
                r->legacy_.release_model(id);
            }),
        .begin_frame = hook(legacy_.begin_frame, &draw<&L::begin_frame>),
        .draw_world = hook(legacy_.draw_world, &draw<&L::draw_world>),
        .draw_brush_entities = hook(legacy_.draw_brush_entities, &draw<&L::draw_brush_entities>),
        .draw_alias_entities = hook(legacy_.draw_alias_entities, &draw<&L::draw_alias_entities>),
        .draw_sprite_entities = hook(legacy_.draw_sprite_entities, &draw<&L::draw_sprite_entities>),
        .draw_particles = hook(legacy_.draw_particles, &draw<&L::draw_particles>),
        .post_process = hook(legacy_.post_process, &LegacyRenderer::post_process),
        .end_frame = hook(legacy_.end_frame, &draw<&L::end_frame>),
        .menu_settings = legacy_.menu_settings,
        .num_menu_settings = legacy_.menu_settings ? legacy_.num_menu_settings : 0,
    };
}

LegacyRenderer::~LegacyRenderer() {
    if (g_resting == &services_) g_resting = nullptr;
}

bool LegacyRenderer::init() {
    LegacyCallScope scope(&services_);
    if (legacy_.init(&engine_) != 0) return false;
    g_resting = &services_;
    return true;
}

void LegacyRenderer::call_shutdown() {
    LegacyCallScope scope(&services_);
    legacy_.shutdown();
}

const nqr1_frame& LegacyRenderer::convert(const nqr_frame& frame) {
    if (converted_any_ && converted_number_ == frame.number) return frame_;
    converted_any_ = true;
    converted_number_ = frame.number;
    frame_ = nqr1_frame{};
    frame_.size = sizeof(nqr1_frame);
    frame_.number = frame.number;
    frame_.time = frame.time;
    frame_.real_time = frame.real_time;
    frame_.frame_time = frame.frame_time;
    frame_.flags = frame.flags;
    std::memcpy(&frame_.camera, frame.camera,
                std::min<size_t>(frame.camera->size, sizeof(nqr1_camera)));
    frame_.camera.size = sizeof(nqr1_camera);
    frame_.world = frame.world;
    frame_.visible_surfaces = frame.visible_surfaces;
    frame_.num_visible_surfaces = frame.num_visible_surfaces;
    frame_.lightstyles = frame.lightstyles;
    frame_.dlights = frame.dlights;
    frame_.num_dlights = frame.num_dlights;
    frame_.particles = frame.particles;
    frame_.num_particles = frame.num_particles;
    std::memcpy(frame_.view_planes, frame.view_planes, sizeof frame_.view_planes);
    convert_entities(frame);
    return frame_;
}

void LegacyRenderer::convert_entities(const nqr_frame& frame) {
    const size_t total =
        size_t(frame.num_brush_entities) + frame.num_alias_entities + frame.num_sprite_entities;
    // Grown only past the largest frame so far; steady state allocates nothing.
    if (entities_.size() < total) {
        entities_.resize(total);
        lists_.resize(total);
    }
    size_t next = 0;
    frame_.brush_entities = convert_list(frame.brush_entities, frame.num_brush_entities, next);
    frame_.num_brush_entities = frame.num_brush_entities;
    frame_.alias_entities = convert_list(frame.alias_entities, frame.num_alias_entities, next);
    frame_.num_alias_entities = frame.num_alias_entities;
    frame_.sprite_entities = convert_list(frame.sprite_entities, frame.num_sprite_entities, next);
    frame_.num_sprite_entities = frame.num_sprite_entities;
}

const nqr1_entity* const* LegacyRenderer::convert_list(const nqr_entity* const* list,
                                                       uint32_t count, size_t& next) {
    const nqr1_entity** out = lists_.data() + next;
    for (uint32_t i = 0; i < count; ++i, ++next) {
        const nqr_entity& in = *list[i];
        nqr1_entity& e = entities_[next];
        std::memcpy(&e, &in, kSharedEntityBytes);
        e.size = sizeof(nqr1_entity);
        convert_light(*in.light, e.light);
        out[i] = &e;
    }
    return out;
}

}  // namespace nq

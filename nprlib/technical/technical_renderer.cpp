#include "technical/technical_renderer.h"

#include <epoxy/gl.h>

#include <algorithm>

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "abi/abi_access.h"
#include "abi/frame_view.h"
#include "classic/classic_pass.h"
#include "technical/alias_pose.h"
#include "technical/planar_shadow.h"

namespace nq::npr::technical {

using npr::entity_in_view;
using npr::frame_readable;
using npr::has_known_prefix;

namespace {

bool wants_alias_edges(const EdgeSettings& settings) {
    return settings.silhouettes || settings.creases;
}

EdgeFrameUniforms edge_frame_uniforms(const nqr_frame& frame) {
    EdgeFrameUniforms out;
    out.projection = npr::mat4_from(frame.camera->projection);
    out.viewport = {static_cast<float>(frame.camera->viewport[2]),
                    static_cast<float>(frame.camera->viewport[3])};
    out.z_near = frame.camera->z_near;
    return out;
}

constexpr double kViewModelDepthMax = 0.3;  // GLQuake's depth-range hack, as classic

}  // namespace

void TechnicalRenderer::log(int level, const std::string& text) const {
    if (engine_ && engine_->log) engine_->log(engine_->context, level, text.c_str());
}

bool TechnicalRenderer::fail(const std::string& message, std::string* error) {
    log(NQR_LOG_ERROR, "technical renderer: " + message);
    if (error) *error = message;
    shutdown();
    return false;
}

bool TechnicalRenderer::init(const nqr_engine* engine, std::string* error) {
    shutdown();
    if (!has_known_prefix(engine)) return fail("engine services struct missing or too old", error);
    engine_ = engine;
    std::string message;
    if (!classic_.init(engine, &message)) return fail(message, error);
    models_.init(&tracker_, classic_.palette(),
                 [this](int level, const std::string& text) { log(level, text); });
    if (!faces_.init(&tracker_, message) || !alias_edges_.init(&tracker_, message) ||
        !brush_edges_.init(&tracker_, message) || !shadows_.init(&tracker_, message)) {
        return fail(message, error);
    }
    items_.reserve(256);
    initialised_ = true;
    return true;
}

void TechnicalRenderer::shutdown() {
    models_.clear();
    shadows_.reset();
    brush_edges_.reset();
    alias_edges_.reset();
    faces_.reset();
    classic_.shutdown();
    initialised_ = false;
}

void TechnicalRenderer::register_model(const nqr_model* model) {
    if (!initialised_ || !model) return;
    classic_.register_model(model);
    models_.add(*model);
}

void TechnicalRenderer::release_model(nqr_model_id id) {
    classic_.release_model(id);
    models_.remove(id);
}

void TechnicalRenderer::pass_begin(const char* name) const {
    if (engine_->gpu_pass_begin) engine_->gpu_pass_begin(engine_->context, name);
}

void TechnicalRenderer::pass_end() const {
    if (engine_->gpu_pass_end) engine_->gpu_pass_end(engine_->context);
}

// ------------------------------------------------------------------ brush geometry

void TechnicalRenderer::draw_world(const nqr_frame* frame) {
    classic_.draw_world(frame);
    if (!initialised_ || !frame_readable(frame) || !settings.edges.world_edges) return;
    const TechnicalModel* world = models_.find(frame->world);
    npr::FrameView view;
    if (!world || !world->brush_edges || !npr::read_frame_view(frame, view)) return;
    pass_begin("edges");
    classic::begin_classic_pass();
    brush_edges_.draw_world(view, edge_frame_uniforms(*frame), *frame, *world->brush_edges,
                            settings.edges);
    classic::end_classic_pass();
    pass_end();
}

void TechnicalRenderer::draw_brush_entities(const nqr_frame* frame) {
    classic_.draw_brush_entities(frame);
    if (!initialised_ || !frame_readable(frame) || !settings.edges.world_edges) return;
    npr::FrameView view;
    if (!frame->brush_entities || frame->num_brush_entities == 0 ||
        !npr::read_frame_view(frame, view)) {
        return;
    }
    pass_begin("edges");
    classic::begin_classic_pass();
    draw_brush_entity_edges(*frame, view);
    classic::end_classic_pass();
    pass_end();
}

void TechnicalRenderer::draw_brush_entity_edges(const nqr_frame& frame,
                                                const npr::FrameView& view) {
    const EdgeFrameUniforms uniforms = edge_frame_uniforms(frame);
    for (uint32_t i = 0; i < frame.num_brush_entities; ++i) {
        const nqr_entity* entity = frame.brush_entities[i];
        if (!entity_in_view(entity) || entity->model == frame.world) continue;
        const TechnicalModel* model = models_.find(entity->model);
        if (!model || !model->brush_edges) continue;
        brush_edges_.draw_entity(view, uniforms, *entity, *model->brush_edges, model->first_surface,
                                 model->num_surfaces, settings.edges);
    }
}

// ------------------------------------------------------------------ alias models

bool TechnicalRenderer::find_alias(const nqr_entity* entity, AliasItem& out) const {
    if (!npr::entity_readable(entity)) return false;
    const classic::RegisteredModel* registered = classic_.models().find(entity->model);
    if (!registered || !registered->alias) return false;
    out.entity = entity;
    out.gpu = registered->alias.get();
    out.image = out.gpu->skin_image(entity->skin, entity->skin_image);
    if (!out.image) return false;
    const TechnicalModel* model = models_.find(entity->model);
    out.edges = model ? model->alias_edges.get() : nullptr;
    out.tones = model ? &model->skin_tones : nullptr;
    out.radius = model ? model->radius * std::max(entity->scale, 1.0f) : 0.0f;
    out.casts_shadow = !model || model->casts_shadow;
    return true;
}

void TechnicalRenderer::draw_alias_entities(const nqr_frame* frame) {
    npr::FrameView view;
    if (!initialised_ || !frame_readable(frame) || !frame->alias_entities ||
        !npr::read_frame_view(frame, view)) {
        return;
    }
    gather_alias_entities(*frame, view);
    classic::begin_classic_pass();
    if (shadows_.triangles_in_batch() > 0) {
        pass_begin("shadows");
        shadows_.draw(settings.shadows);
        pass_end();
    }
    // Timed: the opaque models' faces and edges (nearly all of the work). Translucent models
    // and the view model, drawn after them, count toward the engine's own alias pass: every
    // timer marker costs a query, and on llvmpipe a flush.
    const EdgeFrameUniforms edge_uniforms = edge_frame_uniforms(*frame);
    pass_begin("shading");
    draw_faces(view, AliasPass::opaque);
    pass_end();
    pass_begin("edges");
    draw_alias_edges(edge_uniforms, AliasPass::opaque);
    pass_end();
    draw_faces(view, AliasPass::translucent);
    draw_alias_edges(edge_uniforms, AliasPass::translucent);
    glDepthRange(0.0, kViewModelDepthMax);
    draw_faces(view, AliasPass::view_model);
    draw_alias_edges(edge_uniforms, AliasPass::view_model);
    classic::end_classic_pass();
}

// One CPU walk over the frame's alias entities: each pose is blended once, then flattened into
// the shadow batch and searched for edges; the entities on screen are listed for the passes.
void TechnicalRenderer::gather_alias_entities(const nqr_frame& frame, const npr::FrameView& view) {
    items_.clear();
    shadows_.begin_frame();
    alias_edges_.begin_frame(view, settings.shading,
                             chain_tolerance(edge_frame_uniforms(frame), settings.edges));
    for (uint32_t i = 0; i < frame.num_alias_entities; ++i) {
        AliasItem item;
        if (!find_alias(frame.alias_entities[i], item)) continue;
        const bool on_screen = entity_in_view(item.entity);
        const ShadowPasses shadow = shadow_passes(item, view);
        const bool edges = on_screen && item.edges && wants_alias_edges(settings.edges) &&
                           !edges_fully_faded(item, view);
        if (!on_screen && shadow.count == 0) continue;
        if (on_screen) {
            item.skin =
                classic_.alias_drawer().skin_texture(frame, *item.entity, *item.gpu, *item.image);
            item.fullbright = item.image->fullbright ? item.image->fullbright.id() : 0;
            item.skin_sample = skin_sample(item);
        }
        if ((shadow.count > 0 || edges) && item.edges) {
            pose_.resize(std::max<size_t>(pose_.size(), item.edges->vertex_count()));
            blend_alias_pose(item.gpu->model(), *item.entity, pose_.data());
            if (shadow.count > 0) {
                shadows_.add_entity(view, *item.entity, *item.edges, pose_.data(), shadow);
            }
            if (edges) {
                item.edge_span =
                    alias_edges_.add_entity(*item.entity, *item.gpu, *item.edges, pose_.data(),
                                            item.skin_sample, settings.edges);
            }
        }
        if (on_screen) items_.push_back(item);
    }
    alias_edges_.upload();
}

SkinSample TechnicalRenderer::skin_sample(const AliasItem& item) const {
    const nqr_entity& entity = *item.entity;
    const uint8_t* pixels = item.gpu->skin_pixels(entity.skin, entity.skin_image);
    if (item.tones)
        return item.tones->sample(item.gpu->model(), pixels, entity, classic_.palette());
    return sample_skin(item.gpu->model(), pixels, entity, classic_.palette());
}

// Shadows fade out over the last quarter of tech_shadow_distance instead of popping away.
float TechnicalRenderer::shadow_distance_fade(float distance) const {
    const float far = settings.shadows.max_distance;
    if (far <= 0.0f) return 0.0f;
    return glm::clamp((far - distance) / (0.25f * far), 0.0f, 1.0f);
}

// The entity's shadow projections (count 0: none), faded with distance; casters off screen
// keep theirs only when the shadow can be seen.
ShadowPasses TechnicalRenderer::shadow_passes(const AliasItem& item,
                                              const npr::FrameView& view) const {
    ShadowPasses none;
    if (!settings.shadows.enabled || !item.edges || !item.casts_shadow ||
        classic::alias_pass_of(*item.entity) != AliasPass::opaque) {
        return none;
    }
    const glm::vec3 origin = glm::make_vec3(item.entity->origin);
    const float fade = shadow_distance_fade(glm::distance(origin, view.eye));
    if (fade <= 0.0f) return none;
    const ShadowPlane plane = find_shadow_plane(*engine_, origin, settings.shadows.max_drop);
    if (!plane.found) return none;
    ShadowPasses passes = build_shadow_passes(plane, glm::make_vec3(item.entity->light->direction),
                                              origin, settings.shadows, item.radius);
    if (!entity_in_view(item.entity) &&
        npr::sphere_outside_view(view, passes.bounds_centre, passes.bounds_radius)) {
        return none;
    }
    for (int p = 0; p < passes.count; ++p) passes.pass[p].alpha *= fade;
    return passes;
}

void TechnicalRenderer::draw_faces(const npr::FrameView& view, AliasPass pass) {
    bool begun = false;
    for (const AliasItem& item : items_) {
        if (classic::alias_pass_of(*item.entity) != pass) continue;
        if (!begun) faces_.begin(view, settings.shading);
        begun = true;
        faces_.draw(view, *item.entity, *item.gpu, item.skin, item.fullbright,
                    item.skin_sample.average);
    }
    if (begun) faces_.end();
}

// Past the blend threshold an edge has taken the model's colour: drawing it changes nothing.
bool TechnicalRenderer::edges_fully_faded(const AliasItem& item, const npr::FrameView& view) const {
    if (!settings.edges.distance_fade) return false;
    const float distance = glm::distance(glm::make_vec3(item.entity->origin), view.eye);
    return distance - item.radius > settings.edges.fade_distance;
}

// Entities of one pass whose edges lie next to each other in the batch go in one draw.
void TechnicalRenderer::draw_alias_edges(const EdgeFrameUniforms& uniforms, AliasPass pass) {
    EdgeSpan run{0, 0};
    bool begun = false;
    for (const AliasItem& item : items_) {
        const EdgeSpan span = item.edge_span;
        if (span.edge_count == 0 || classic::alias_pass_of(*item.entity) != pass) continue;
        if (!begun) alias_edges_.begin(uniforms, settings.edges);
        begun = true;
        if (run.edge_count > 0 && run.first_edge + run.edge_count == span.first_edge) {
            run.edge_count += span.edge_count;
            continue;
        }
        alias_edges_.draw(run);
        run = span;
    }
    if (!begun) return;
    alias_edges_.draw(run);
    alias_edges_.end();
}

}  // namespace nq::npr::technical

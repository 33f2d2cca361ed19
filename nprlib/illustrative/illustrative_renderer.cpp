#include "illustrative/illustrative_renderer.h"

#include <epoxy/gl.h>

#include "abi/abi_access.h"
#include "abi/frame_view.h"
#include "classic/classic_pass.h"
#include "illustrative/texture_abstraction.h"

namespace nq::npr::illustrative {

using npr::entity_in_view;
using npr::frame_readable;
using npr::has_known_prefix;

namespace {

constexpr double kViewModelDepthMax = 0.3;  // GLQuake's depth-range hack, as classic
constexpr char kDefaultRamp[] = "tf2";

}  // namespace

void IllustrativeRenderer::log(int level, const std::string& text) const {
    if (engine_ && engine_->log) engine_->log(engine_->context, level, text.c_str());
}

bool IllustrativeRenderer::fail(const std::string& message, std::string* error) {
    log(NQR_LOG_ERROR, "illustrative renderer: " + message);
    if (error) *error = message;
    shutdown();
    return false;
}

std::optional<std::vector<uint8_t>> IllustrativeRenderer::read_file(const std::string& path) const {
    if (!engine_ || !engine_->file_read || !engine_->file_free) return std::nullopt;
    nqr_blob blob{};
    blob.size = sizeof(nqr_blob);
    if (engine_->file_read(engine_->context, path.c_str(), &blob) != 0) return std::nullopt;
    std::vector<uint8_t> bytes(blob.data, blob.data + blob.length);
    engine_->file_free(engine_->context, &blob);
    return bytes;
}

bool IllustrativeRenderer::init(const nqr_engine* engine, std::string* error) {
    shutdown();
    if (!has_known_prefix(engine)) return fail("engine services struct missing or too old", error);
    engine_ = engine;
    std::string message;
    if (!classic_.init(engine, &message)) return fail(message, error);
    classic_.set_brush_texture_filter([this](int width, int height, std::vector<uint8_t>& rgba) {
        abstract_world_texture(width, height, rgba);
    });
    models_.init(
        &tracker_, classic_.palette(), [this](const std::string& path) { return read_file(path); },
        [this](int level, const std::string& text) { log(level, text); });
    if (!drawer_.init(&tracker_, message)) return fail(message, error);
    items_.reserve(256);
    initialised_ = true;
    load_warp_ramp();
    return true;
}

void IllustrativeRenderer::shutdown() {
    items_.clear();
    models_.clear();
    warp_.reset();
    warp_name_.clear();
    drawer_.reset();
    classic_.shutdown();
    initialised_ = false;
}

void IllustrativeRenderer::abstract_world_texture(int width, int height,
                                                  std::vector<uint8_t>& rgba) const {
    if (!settings.abstract_world) return;
    AbstractionSettings abstraction;
    abstraction.radius = settings.abstract_radius;
    abstraction.saturation = settings.world_saturation;
    abstraction.contrast = settings.world_contrast;
    std::vector<uint8_t> out = abstract_texture_rgba(rgba, width, height, abstraction);
    if (out.size() == rgba.size()) rgba.swap(out);
}

void IllustrativeRenderer::register_model(const nqr_model* model) {
    if (!initialised_ || !model) return;
    classic_.register_model(model);
    if (!has_known_prefix(model)) return;
    models_.add(*model, {settings.smooth_normals, settings.crease_angle_degrees});
}

void IllustrativeRenderer::release_model(nqr_model_id id) {
    classic_.release_model(id);
    models_.remove(id);
}

// The style's ramp: a built-in name or an image in the game's files; anything unusable is
// reported once and the TF2 ramp drawn instead.
void IllustrativeRenderer::load_warp_ramp() {
    warp_name_ = settings.warp_ramp;
    WarpRampResult ramp = find_warp_ramp(
        warp_name_, [this](const std::string& path) { return read_file(path); },
        classic_.palette());
    if (!ramp.ramp) {
        log(NQR_LOG_WARNING, "illustrative: ill_ramp \"" + warp_name_ + "\": " + ramp.error +
                                 "; using the " + kDefaultRamp + " ramp");
        ramp.ramp = builtin_warp_ramp(kDefaultRamp);
    }
    warp_ = create_warp_texture(&tracker_, *ramp.ramp);
}

void IllustrativeRenderer::begin_frame() {
    if (initialised_ && settings.warp_ramp != warp_name_) load_warp_ramp();
}

bool IllustrativeRenderer::gather(const nqr_frame& frame, const nqr_entity* entity,
                                  AliasItem& out) {
    if (!has_known_prefix(entity) || !entity_in_view(entity)) return false;
    const classic::RegisteredModel* registered = classic_.models().find(entity->model);
    if (!registered || !registered->alias) return false;
    const classic::SkinImageGpu* image =
        registered->alias->skin_image(entity->skin, entity->skin_image);
    if (!image) return false;
    out.entity = entity;
    out.gpu = registered->alias.get();
    out.data = models_.find(entity->model);
    out.textures.skin = classic_.alias_drawer().skin_texture(frame, *entity, *out.gpu, *image);
    out.textures.fullbright = image->fullbright ? image->fullbright.id() : 0;
    if (out.data) {
        out.textures.masks = out.data->masks_for(entity->skin, entity->skin_image);
        out.textures.warp = out.data->warp.id();
    }
    return true;
}

void IllustrativeRenderer::draw_alias_entities(const nqr_frame* frame) {
    npr::FrameView view;
    if (!initialised_ || !frame_readable(frame) || !frame->alias_entities ||
        !npr::read_frame_view(frame, view)) {
        return;
    }
    items_.clear();
    for (uint32_t i = 0; i < frame->num_alias_entities; ++i) {
        AliasItem item;
        if (gather(*frame, frame->alias_entities[i], item)) items_.push_back(item);
    }
    classic::begin_classic_pass();
    if (engine_->gpu_pass_begin) engine_->gpu_pass_begin(engine_->context, "shading");
    draw_pass(*frame, view, AliasPass::opaque);
    if (engine_->gpu_pass_end) engine_->gpu_pass_end(engine_->context);
    draw_pass(*frame, view, AliasPass::translucent);
    glDepthRange(0.0, kViewModelDepthMax);
    draw_pass(*frame, view, AliasPass::view_model);
    classic::end_classic_pass();
}

void IllustrativeRenderer::draw_pass(const nqr_frame& frame, const npr::FrameView& view,
                                     AliasPass pass) {
    bool begun = false;
    for (const AliasItem& item : items_) {
        if (!item.data || classic::alias_pass_of(*item.entity) != pass) continue;
        if (!begun && !drawer_.begin(view, settings, warp_.id())) return;
        begun = true;
        const MaterialParams material = apply_overrides(settings.material, item.data->material);
        drawer_.draw(view, *item.entity, *item.gpu, *item.data->mesh, item.textures, material);
    }
    if (begun) drawer_.end();
    // Models the style could not prepare keep the classic look rather than vanish.
    for (const AliasItem& item : items_) {
        if (item.data || classic::alias_pass_of(*item.entity) != pass) continue;
        classic_.alias_drawer().draw_entity(frame, view, *item.entity, *item.gpu);
    }
}

}  // namespace nq::npr::illustrative

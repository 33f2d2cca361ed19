#include "technical/technical_models.h"

#include <algorithm>
#include <span>

#include "abi/abi_access.h"
#include "gl/palette_image.h"

namespace nq::npr::technical {

using npr::has_known_prefix;

void TechnicalModels::init(gl::ObjectTracker* tracker, const uint8_t* palette_rgb, Logger log) {
    clear();
    tracker_ = tracker;
    palette_ = palette_rgb;
    log_ = std::move(log);
}

void TechnicalModels::add(const nqr_model& model) {
    remove(model.id);
    TechnicalModel entry;
    entry.radius = model.radius;
    if (model.kind == NQR_MODEL_ALIAS && has_known_prefix(model.alias)) add_alias(model, entry);
    if (model.kind == NQR_MODEL_BRUSH && has_known_prefix(model.brush)) add_brush(model, entry);
    models_.emplace(model.id, std::move(entry));
}

float fullbright_share(const nqr_alias_model& model) {
    if (model.num_skins == 0 || !has_known_prefix(model.skins)) return 0.0f;
    const nqr_alias_skin& skin = npr::abi_element(model.skins, 0);
    if (skin.num_images == 0 || !skin.images || !skin.images[0]) return 0.0f;
    const size_t pixels =
        size_t(std::max(model.skin_width, 0)) * size_t(std::max(model.skin_height, 0));
    if (pixels == 0) return 0.0f;
    const std::span<const uint8_t> image(skin.images[0], pixels);
    const auto bright = std::count_if(image.begin(), image.end(), gl::is_fullbright_index);
    return static_cast<float>(bright) / static_cast<float>(pixels);
}

void TechnicalModels::add_alias(const nqr_model& model, TechnicalModel& out) {
    const std::string name = model.name ? model.name : "?";
    out.casts_shadow = fullbright_share(*model.alias) < kLightSkinShare;
    out.skin_tones.build(*model.alias);
    std::string error;
    out.alias_edges = AliasEdgeMesh::create(*model.alias, error);
    if (!out.alias_edges) {
        log_(NQR_LOG_WARNING, "technical: " + name + ": no edges: " + error);
        return;
    }
    log_(NQR_LOG_DEBUG, out.alias_edges->verdict_line(name));
}

void TechnicalModels::add_brush(const nqr_model& model, TechnicalModel& out) {
    const nqr_brush_model* brush = model.brush;
    SharedBrush& shared = brushes_[brush];
    if (!shared.mesh) {
        std::string error;
        shared.mesh = BrushEdgeMesh::create(tracker_, *brush, error, palette_);
        if (!shared.mesh) {
            brushes_.erase(brush);
            log_(NQR_LOG_WARNING, std::string("technical: ") + (model.name ? model.name : "?") +
                                      ": no brush edges: " + error);
            return;
        }
    }
    ++shared.users;
    brush_of_[model.id] = brush;
    out.brush_edges = shared.mesh.get();
    const uint32_t total = brush->num_surfaces;
    out.first_surface = std::min(model.first_surface, total);
    out.num_surfaces = std::min(model.num_surfaces, total - out.first_surface);
}

void TechnicalModels::remove(nqr_model_id id) {
    auto brush = brush_of_.find(id);
    if (brush != brush_of_.end()) {
        auto shared = brushes_.find(brush->second);
        if (shared != brushes_.end() && --shared->second.users <= 0) brushes_.erase(shared);
        brush_of_.erase(brush);
    }
    models_.erase(id);
}

void TechnicalModels::clear() {
    models_.clear();
    brush_of_.clear();
    brushes_.clear();
}

const TechnicalModel* TechnicalModels::find(nqr_model_id id) const {
    auto it = models_.find(id);
    return it == models_.end() ? nullptr : &it->second;
}

}  // namespace nq::npr::technical

#include "classic/model_registry.h"

#include <algorithm>

#include "abi/abi_access.h"

namespace nq::npr::classic {

void ModelRegistry::init(gl::ObjectTracker* tracker, const uint8_t* palette_rgb) {
    tracker_ = tracker;
    palette_ = palette_rgb;
}

bool ModelRegistry::add_brush(const nqr_model& model, RegisteredModel& out, std::string& error) {
    if (!model.brush) {
        error = "brush model without brush data";
        return false;
    }
    SharedBrush& shared = brushes_[model.brush];
    if (!shared.gpu) {
        shared.gpu = BrushModelGpu::create(tracker_, *model.brush, palette_, error, &brush_filter_);
        if (!shared.gpu) {
            brushes_.erase(model.brush);
            return false;
        }
    }
    ++shared.users;
    out.brush = shared.gpu.get();
    out.brush_source = model.brush;
    const uint32_t total = shared.gpu->num_surfaces();
    out.first_surface = std::min(model.first_surface, total);
    out.num_surfaces = std::min(model.num_surfaces, total - out.first_surface);
    return true;
}

bool ModelRegistry::add(const nqr_model& model, std::string& error) {
    if (!has_known_prefix(&model) || model.id == 0) {
        error = "model struct of an unknown size or with id 0";
        return false;
    }
    remove(model.id);
    RegisteredModel registered;
    registered.kind = model.kind;
    bool ok = false;
    switch (model.kind) {
        case NQR_MODEL_BRUSH:
            ok = add_brush(model, registered, error);
            break;
        case NQR_MODEL_ALIAS:
            if (model.alias)
                registered.alias = AliasModelGpu::create(tracker_, *model.alias, palette_, error);
            if (!model.alias && error.empty()) error = "alias model without alias data";
            ok = registered.alias != nullptr;
            break;
        case NQR_MODEL_SPRITE:
            if (model.sprite)
                registered.sprite =
                    SpriteModelGpu::create(tracker_, *model.sprite, palette_, error);
            if (!model.sprite && error.empty()) error = "sprite model without sprite data";
            ok = registered.sprite != nullptr;
            break;
        default:
            error = "unknown model kind " + std::to_string(model.kind);
            break;
    }
    if (!ok) return false;
    models_.emplace(model.id, std::move(registered));
    return true;
}

void ModelRegistry::remove(nqr_model_id id) {
    auto found = models_.find(id);
    if (found == models_.end()) return;
    if (found->second.brush_source) {
        auto shared = brushes_.find(found->second.brush_source);
        if (shared != brushes_.end() && --shared->second.users <= 0) brushes_.erase(shared);
    }
    models_.erase(found);
}

void ModelRegistry::clear() {
    models_.clear();
    brushes_.clear();
}

const RegisteredModel* ModelRegistry::find(nqr_model_id id) const {
    auto found = models_.find(id);
    return found == models_.end() ? nullptr : &found->second;
}

}  // namespace nq::npr::classic

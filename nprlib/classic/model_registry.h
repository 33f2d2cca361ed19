// The classic renderer's models by id: brush models (sharing one BrushModelGpu per
// nqr_brush_model: the world and its "*N" submodels), alias models and sprites. Lookups during a
// frame never allocate.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <unordered_map>
#include <utility>

#include "classic/alias_model_gpu.h"
#include "classic/brush_model_gpu.h"
#include "classic/sprite_model_gpu.h"
#include "gl/object_tracker.h"
#include "nqr_renderer.h"

namespace nq::npr::classic {

struct RegisteredModel {
    uint32_t kind = 0;  // nqr_model_kind
    BrushModelGpu* brush = nullptr;
    const nqr_brush_model* brush_source = nullptr;
    uint32_t first_surface = 0, num_surfaces = 0;  // clamped to the brush's surfaces
    std::unique_ptr<AliasModelGpu> alias;
    std::unique_ptr<SpriteModelGpu> sprite;
};

class ModelRegistry {
  public:
    void init(gl::ObjectTracker* tracker, const uint8_t* palette_rgb);
    // Applied to the base colours of brush models registered from now on (create_brush_textures).
    void set_brush_texture_filter(gl::RgbaFilter filter) { brush_filter_ = std::move(filter); }

    // Uploads the model; false with `error` when its data cannot be used (it is then unknown).
    // Registering an id again replaces the old model.
    bool add(const nqr_model& model, std::string& error);
    void remove(nqr_model_id id);
    void clear();

    const RegisteredModel* find(nqr_model_id id) const;
    size_t size() const { return models_.size(); }
    size_t brush_geometry_count() const { return brushes_.size(); }

  private:
    struct SharedBrush {
        std::unique_ptr<BrushModelGpu> gpu;
        int users = 0;
    };

    bool add_brush(const nqr_model& model, RegisteredModel& out, std::string& error);

    gl::ObjectTracker* tracker_ = nullptr;
    const uint8_t* palette_ = nullptr;
    gl::RgbaFilter brush_filter_;
    std::unordered_map<nqr_model_id, RegisteredModel> models_;
    std::unordered_map<const nqr_brush_model*, SharedBrush> brushes_;
};

}  // namespace nq::npr::classic

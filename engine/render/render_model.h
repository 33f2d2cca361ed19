// One model as the renderer ABI sees it (nqr_model), together with the parsed data it points
// into. Brush models built from one map (the world "maps/x.bsp" and its inline submodels "*N")
// share one BrushModelData and differ in their surface range and bounds.
#pragma once

#include <memory>
#include <string>

#include "nqr_renderer.h"
#include "render/alias_model.h"
#include "render/brush_model.h"
#include "render/sprite_model.h"

namespace nq {

class RenderModel {
  public:
    // Brush model `submodel` (0 = the map's own model) of `data`.
    static std::unique_ptr<RenderModel> brush(std::string name,
                                              std::shared_ptr<const BrushModelData> data,
                                              size_t submodel);
    static std::unique_ptr<RenderModel> alias(std::string name,
                                              std::shared_ptr<const AliasModelData> data,
                                              bool placeholder = false);
    static std::unique_ptr<RenderModel> sprite(std::string name,
                                               std::shared_ptr<const SpriteModelData> data);

    RenderModel(const RenderModel&) = delete;
    RenderModel& operator=(const RenderModel&) = delete;

    // Stays valid (same address) as long as this RenderModel lives.
    const nqr_model* abi() const { return &model_; }
    nqr_model_id id() const { return model_.id; }
    void set_id(nqr_model_id id) { model_.id = id; }
    const std::string& name() const { return name_; }
    uint32_t kind() const { return model_.kind; }
    // True for the stand-in of a model that failed to load.
    bool placeholder() const { return placeholder_; }

    // The parsed data behind the model; null for other kinds.
    const BrushModelData* brush_data() const { return brush_.get(); }
    const AliasModelData* alias_data() const { return alias_.get(); }
    const SpriteModelData* sprite_data() const { return sprite_.get(); }

  private:
    RenderModel() = default;
    void set_bounds(const float mins[3], const float maxs[3]);

    std::string name_;
    bool placeholder_ = false;
    std::shared_ptr<const BrushModelData> brush_;
    std::shared_ptr<const AliasModelData> alias_;
    std::shared_ptr<const SpriteModelData> sprite_;
    nqr_model model_{};
};

}  // namespace nq

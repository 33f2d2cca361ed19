// The technical style's own per-model data, next to the classic GPU data it reuses (skins,
// poses, brush geometry): recovered adjacency for every alias model and shared-edge tables for
// every brush model (the world and its "*N" submodels share one table per nqr_brush_model).
// Built once at registration; lookups during a frame never allocate.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <unordered_map>

#include "gl/object_tracker.h"
#include "nqr_renderer.h"
#include "technical/alias_edge_mesh.h"
#include "technical/brush_edge_mesh.h"
#include "technical/skin_tones.h"

namespace nq::npr::technical {

struct TechnicalModel {
    std::unique_ptr<AliasEdgeMesh> alias_edges;  // alias models
    SkinTones skin_tones;                        // alias models
    const BrushEdgeMesh* brush_edges = nullptr;  // brush models (shared)
    uint32_t first_surface = 0, num_surfaces = 0;
    float radius = 0;  // bounding radius about the model origin (nqr_model.radius)
    // False for a model that is itself a light (flames, torches, lava balls, bolts): its first
    // skin is at least kLightSkinShare fullbright. A light casts no shadow.
    bool casts_shadow = true;
};

inline constexpr float kLightSkinShare = 0.4f;

// Share of an alias model's first skin image that is fullbright colours (0 without skins).
float fullbright_share(const nqr_alias_model& model);

class TechnicalModels {
  public:
    using Logger = std::function<void(int level, const std::string& text)>;

    // palette_rgb (768 bytes) must outlive this object: brush edges take their surface colour
    // from the textures' average colour through it.
    void init(gl::ObjectTracker* tracker, const uint8_t* palette_rgb, Logger log);
    // Builds the model's edge data; unusable data is logged and the model gets none (it is then
    // drawn without edges). Registering an id again replaces the old data.
    void add(const nqr_model& model);
    void remove(nqr_model_id id);
    void clear();

    const TechnicalModel* find(nqr_model_id id) const;

  private:
    struct SharedBrush {
        std::unique_ptr<BrushEdgeMesh> mesh;
        int users = 0;
    };
    void add_alias(const nqr_model& model, TechnicalModel& out);
    void add_brush(const nqr_model& model, TechnicalModel& out);

    gl::ObjectTracker* tracker_ = nullptr;
    const uint8_t* palette_ = nullptr;
    Logger log_;
    std::unordered_map<nqr_model_id, TechnicalModel> models_;
    std::unordered_map<const nqr_brush_model*, SharedBrush> brushes_;
    std::unordered_map<nqr_model_id, const nqr_brush_model*> brush_of_;
};

}  // namespace nq::npr::technical

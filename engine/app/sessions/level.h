// The loaded map and its models, bound to a demo's model precache list: what the client names
// by precache index, the renderer knows by model id. Rebuilt when the client's generation
// changes (a new svc_serverinfo).
#pragma once

#include <future>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "client/client_state.h"
#include "render/ambient_cube_field.h"
#include "render/light_sampler.h"
#include "render/model_cache.h"
#include "render/occlusion_culler.h"
#include "render/surface_reflectivity.h"
#include "render/world_culler.h"

namespace nq {

class Level {
  public:
    explicit Level(ModelCache::FileReader reader) : cache_(std::move(reader)) {}

    // Loads the world (model_names()[1]) and every precached model; missing models become
    // placeholders with a warning. Sets the client's model info. Fails only if the world does.
    // At load it also starts baking the map's ambient cube field (ambient_cube_bake.h), with
    // surface colours from `palette` (set_palette; without one every surface reflects half).
    Result<bool> load(ClientState& client);
    void clear();
    // A server restarting the same map (a new serverinfo naming the same models, as Quake's
    // `restart` and a changelevel to the same map send): the loaded level serves again, and
    // only the client's model info is set anew.
    bool holds(std::span<const std::string> model_names) const;
    void reattach(ClientState& client) const { client.set_model_info(model_info_); }
    void set_palette(const PaletteBytes& palette) { palette_ = palette; }

    bool loaded() const { return world_ != nullptr; }
    const ModelCache& models() const { return cache_; }
    // The id of precache index `index` (0 when none).
    nqr_model_id model_id(int index) const;
    uint32_t model_kind(nqr_model_id id) const;
    const Bsp* world_bsp() const;
    WorldCuller* culler() { return culler_.get(); }
    OcclusionCuller* occlusion() { return occlusion_.get(); }
    // The ambient cube field is baked on worker threads from the moment the world has loaded,
    // while the other models load and register with the renderer; the first of these three
    // to be asked waits for it (on the main thread, as everything else here).
    const LightSampler* light_sampler() const {
        finish_ambient_bake();
        return lights_.get();
    }
    const AmbientCubeField* ambient_field() const {
        finish_ambient_bake();
        return ambient_.get();
    }
    // Wall-clock seconds the bake of the last load took.
    double ambient_bake_seconds() const {
        finish_ambient_bake();
        return ambient_bake_seconds_;
    }
    std::vector<std::string> take_warnings();

  private:
    struct BakedField {
        AmbientCubeField field;
        double seconds = 0.0;
    };
    void start_ambient_bake(const BrushModelData& data);
    void finish_ambient_bake() const;

    ModelCache cache_;
    const RenderModel* world_ = nullptr;
    std::vector<nqr_model_id> ids_;  // by precache index
    std::vector<std::string> model_names_;
    std::vector<ModelInfo> model_info_;
    std::unique_ptr<WorldCuller> culler_;
    std::unique_ptr<OccluderMesh> occluders_;
    std::unique_ptr<OcclusionCuller> occlusion_;
    // Declared after cache_, so destroyed (waiting for the bake) before the world it reads.
    mutable std::future<BakedField> baking_;
    mutable std::vector<LightEntity> light_entities_;  // until the bake ends
    mutable std::unique_ptr<AmbientCubeField> ambient_;
    mutable std::unique_ptr<LightSampler> lights_;
    std::optional<PaletteBytes> palette_;
    mutable double ambient_bake_seconds_ = 0.0;
    std::vector<std::string> warnings_;
};

}  // namespace nq

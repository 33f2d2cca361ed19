// The loaded map and its models, bound to a demo's model precache list: what the client names
// by precache index, the renderer knows by model id. Rebuilt when the client's generation
// changes (a new svc_serverinfo).
#pragma once

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
    // At load it also bakes the map's ambient cube field (ambient_cube_bake.h), with surface
    // colours from `palette` (set_palette; without one every surface reflects half).
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
    const LightSampler* light_sampler() const { return lights_.get(); }
    const AmbientCubeField* ambient_field() const { return ambient_.get(); }
    // Wall-clock seconds the last load spent baking the ambient cube field.
    double ambient_bake_seconds() const { return ambient_bake_seconds_; }
    std::vector<std::string> take_warnings();

  private:
    void bake_ambient_field(const BrushModelData& data);

    ModelCache cache_;
    const RenderModel* world_ = nullptr;
    std::vector<nqr_model_id> ids_;  // by precache index
    std::vector<std::string> model_names_;
    std::vector<ModelInfo> model_info_;
    std::unique_ptr<WorldCuller> culler_;
    std::unique_ptr<OccluderMesh> occluders_;
    std::unique_ptr<OcclusionCuller> occlusion_;
    std::unique_ptr<AmbientCubeField> ambient_;
    std::unique_ptr<LightSampler> lights_;
    std::optional<PaletteBytes> palette_;
    double ambient_bake_seconds_ = 0.0;
    std::vector<std::string> warnings_;
};

}  // namespace nq

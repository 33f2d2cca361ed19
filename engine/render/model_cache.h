// The models of the current map by name, as renderer-ABI models with stable ids.
//
// Ids are 1-based and handed out in the order models are first asked for; they stay valid until
// the next load_world() or clear(). load_world() registers the map (id 1) and then its inline
// submodels "*1".."*N" (ids 2..N+1), which is the order of Quake's model precache list, so a
// client that loads the rest of the list in order gets id == precache index.
//
// What a model is, its file's first bytes say (model_format.h), not its name.
// A model that cannot be read or parsed never fails the map: it gets a placeholder (a small red
// box, placeholder_model.h) under its name and a warning. Only the world map itself can fail.
#pragma once

#include <functional>
#include <memory>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include "common/result.h"
#include "render/render_model.h"

namespace nq {

class ModelCache {
  public:
    // Reads a game file by its path ("progs/player.mdl"); an error means missing or unreadable.
    // The engine passes the VFS (vfs_file_reader.h).
    using FileReader = std::function<Result<std::vector<uint8_t>>(const std::string& path)>;

    explicit ModelCache(FileReader reader);

    // Forgets every model, then loads `map_name` ("maps/e1m1.bsp", with "maps/e1m1.lit" when
    // present) as the world and registers its submodels. Returns the world's id (1).
    Result<nqr_model_id> load_world(const std::string& map_name);
    // The id of `name`, loading it first if needed: "*N" (a submodel of the world), any other
    // .bsp (a standalone brush model such as maps/b_batt0.bsp), .mdl or .spr. Never 0.
    nqr_model_id load(const std::string& name);
    // 0 when `name` has not been loaded.
    nqr_model_id find(const std::string& name) const;

    // Null for 0 or an unknown id.
    const RenderModel* get(nqr_model_id id) const;
    const RenderModel* world() const { return get(world_id_); }
    // All models, index i holding id i + 1.
    const std::vector<std::unique_ptr<RenderModel>>& models() const { return models_; }

    void clear();
    // Warnings gathered since the last call (missing models, parser findings, animation gaps).
    std::vector<std::string> take_warnings();

  private:
    nqr_model_id add(std::unique_ptr<RenderModel> model);
    std::unique_ptr<RenderModel> load_model(const std::string& name);
    std::unique_ptr<RenderModel> load_submodel(const std::string& name);
    Result<std::shared_ptr<const BrushModelData>> load_brush_data(const std::string& name);
    Result<std::shared_ptr<const BrushModelData>> brush_data_from(std::span<const uint8_t> bytes,
                                                                  const std::string& name);
    std::unique_ptr<RenderModel> placeholder(const std::string& name, const std::string& why);
    void note_warnings(const std::string& name, const std::vector<std::string>& warnings);

    FileReader reader_;
    std::vector<std::unique_ptr<RenderModel>> models_;
    std::unordered_map<std::string, nqr_model_id> ids_;  // lower-case name -> id
    nqr_model_id world_id_ = 0;
    std::vector<std::string> warnings_;
};

}  // namespace nq

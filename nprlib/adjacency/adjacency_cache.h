// Recovered adjacency per registered model, for a renderer plugin: built once when the model is
// first asked for (register_model time), its verdict logged once, released with the model.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <unordered_map>

#include "adjacency/model_adjacency.h"
#include "nqr_renderer.h"

namespace nq::npr::adjacency {

class AdjacencyCache {
  public:
    // `log` is the engine's (nqr_engine::log); may be null.
    using LogFn = void (*)(int level, const char* text);
    explicit AdjacencyCache(LogFn log, double min_manifold_share = kMinManifoldShare)
        : log_(log), min_share_(min_manifold_share) {}

    // The model's adjacency, built and logged on the first call for `id`.
    const ModelAdjacency& get(nqr_model_id id, const std::string& name,
                              const nqr_alias_model& model);
    const ModelAdjacency* find(nqr_model_id id) const;
    void release(nqr_model_id id) { models_.erase(id); }
    void clear() { models_.clear(); }
    size_t size() const { return models_.size(); }

  private:
    LogFn log_;
    double min_share_;
    std::unordered_map<nqr_model_id, std::unique_ptr<ModelAdjacency>> models_;
};

}  // namespace nq::npr::adjacency

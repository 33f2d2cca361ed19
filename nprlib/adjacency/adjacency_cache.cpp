#include "adjacency/adjacency_cache.h"

namespace nq::npr::adjacency {

const ModelAdjacency& AdjacencyCache::get(nqr_model_id id, const std::string& name,
                                          const nqr_alias_model& model) {
    auto it = models_.find(id);
    if (it != models_.end()) return *it->second;
    auto built = std::make_unique<ModelAdjacency>(recover_adjacency(model, min_share_));
    if (log_) {
        const int level = built->problems.empty() ? NQR_LOG_INFO : NQR_LOG_WARNING;
        log_(level, verdict_log_line(name, *built).c_str());
    }
    return *models_.emplace(id, std::move(built)).first->second;
}

const ModelAdjacency* AdjacencyCache::find(nqr_model_id id) const {
    auto it = models_.find(id);
    return it == models_.end() ? nullptr : it->second.get();
}

}  // namespace nq::npr::adjacency

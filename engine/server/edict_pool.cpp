#include "server/edict_pool.h"

#include <algorithm>

namespace nq::server {

void EdictPool::reset(vm::Vm& vm, uint32_t max_clients) {
    max_clients_ = max_clients;
    free_.assign(vm.max_edicts(), 1);
    free_time_.assign(vm.max_edicts(), 0.0f);
    const uint32_t used = std::min(max_clients + 1, vm.max_edicts());
    for (uint32_t e = 0; e < vm.max_edicts(); ++e) vm.clear_edict(e);
    for (uint32_t e = 0; e < used; ++e) free_[e] = 0;
    vm.set_num_edicts(used);
}

std::optional<uint32_t> EdictPool::alloc(vm::Vm& vm, double time) {
    const uint32_t first = max_clients_ + 1;
    for (uint32_t e = first; e < vm.num_edicts(); ++e) {
        // The first couple of seconds of a level may reuse at once (Quake's rule).
        if (free_[e] && (free_time_[e] < 2.0f || time - free_time_[e] > kReuseDelay)) {
            vm.clear_edict(e);
            free_[e] = 0;
            return e;
        }
    }
    const uint32_t e = vm.num_edicts();
    if (e >= vm.max_edicts()) return std::nullopt;
    vm.set_num_edicts(e + 1);
    vm.clear_edict(e);
    free_[e] = 0;
    return e;
}

void EdictPool::free(vm::Vm& vm, const ProgsLayout& layout, uint32_t edict, double time) {
    if (edict >= free_.size()) return;
    const FieldOffsets& f = layout.fields;
    for (uint32_t field :
         {f.model, f.takedamage, f.modelindex, f.colormap, f.skin, f.frame, f.solid}) {
        vm.set_field_int(edict, field, 0);
    }
    vm.set_field_vector(edict, f.origin, {0, 0, 0});
    vm.set_field_vector(edict, f.angles, {0, 0, 0});
    vm.set_field_float(edict, f.nextthink, -1);
    free_[edict] = 1;
    free_time_[edict] = float(time);
}

void EdictPool::set_free(uint32_t edict, bool free) {
    if (edict < free_.size()) free_[edict] = free ? 1 : 0;
}

}  // namespace nq::server

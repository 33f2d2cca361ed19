#include "classic/surface_batches.h"

#include <algorithm>

namespace nq::npr::classic {

void SurfaceBatches::resize(size_t num_surfaces, size_t num_texture_slots) {
    head_.assign(num_texture_slots, -1);
    tail_.assign(num_texture_slots, -1);
    next_.assign(num_surfaces, -1);
    seen_.assign(num_surfaces, 0);
    touched_.assign(num_texture_slots, 0);
    counts_.assign(num_surfaces, 0);
    offsets_.assign(num_surfaces, nullptr);
    batches_.assign(num_texture_slots, SurfaceBatch{});
    touched_count_ = batch_count_ = 0;
    generation_ = 0;
}

void SurfaceBatches::begin() {
    for (size_t i = 0; i < touched_count_; ++i) head_[touched_[i]] = -1;
    touched_count_ = 0;
    batch_count_ = 0;
    if (++generation_ == 0) {  // wrapped: forget every old stamp
        std::fill(seen_.begin(), seen_.end(), 0);
        generation_ = 1;
    }
}

void SurfaceBatches::add(uint32_t surface, uint32_t texture_slot) {
    if (surface >= seen_.size() || texture_slot >= head_.size()) return;
    if (seen_[surface] == generation_) return;
    seen_[surface] = generation_;
    const auto index = static_cast<int32_t>(surface);
    next_[surface] = -1;
    if (head_[texture_slot] < 0) {
        touched_[touched_count_++] = texture_slot;
        head_[texture_slot] = index;
    } else {
        next_[static_cast<size_t>(tail_[texture_slot])] = index;
    }
    tail_[texture_slot] = index;
}

void SurfaceBatches::finish(const std::vector<BrushSurfaceMesh>& surfaces) {
    uint32_t cursor = 0;
    for (size_t i = 0; i < touched_count_; ++i) {
        const uint32_t slot = touched_[i];
        SurfaceBatch& batch = batches_[batch_count_];
        batch = {slot, cursor, 0};
        for (int32_t s = head_[slot]; s >= 0; s = next_[static_cast<size_t>(s)]) {
            const BrushSurfaceMesh& mesh = surfaces[static_cast<size_t>(s)];
            if (mesh.index_count == 0) continue;
            counts_[cursor] = static_cast<GLsizei>(mesh.index_count);
            offsets_[cursor] =
                reinterpret_cast<const void*>(static_cast<uintptr_t>(mesh.first_index) * 4u);
            ++cursor;
            ++batch.count;
        }
        if (batch.count > 0) ++batch_count_;
    }
}

}  // namespace nq::npr::classic

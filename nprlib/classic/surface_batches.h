// Groups a frame's surfaces of one brush model by the texture they draw with (after animation),
// into the count/offset arrays glMultiDrawElements takes: one draw call per texture. Every array
// is sized when the model is registered, so building batches never allocates.
#pragma once

#include <epoxy/gl.h>

#include <cstdint>
#include <span>
#include <vector>

#include "classic/brush_mesh.h"

namespace nq::npr::classic {

struct SurfaceBatch {
    uint32_t texture_slot;  // index into the model's BrushTextureGpu list
    uint32_t first;         // into counts() / offsets()
    uint32_t count;
};

class SurfaceBatches {
  public:
    void resize(size_t num_surfaces, size_t num_texture_slots);

    void begin();
    // Adds a surface once per frame (repeats are ignored) to the end of its texture's batch: a
    // batch keeps the order its surfaces came in (the engine's list is front to back, which
    // lets depth testing skip the shading of what is hidden).
    void add(uint32_t surface, uint32_t texture_slot);
    void finish(const std::vector<BrushSurfaceMesh>& surfaces);

    std::span<const SurfaceBatch> batches() const { return {batches_.data(), batch_count_}; }
    const GLsizei* counts() const { return counts_.data(); }
    const void* const* offsets() const { return offsets_.data(); }

  private:
    std::vector<int32_t> head_;   // per texture slot: first surface added, -1 none
    std::vector<int32_t> tail_;   // per texture slot: last surface added
    std::vector<int32_t> next_;   // per surface: the next one added with the same slot
    std::vector<uint32_t> seen_;  // per surface: generation it was added in
    std::vector<uint32_t> touched_;
    size_t touched_count_ = 0;
    uint32_t generation_ = 0;
    std::vector<GLsizei> counts_;
    std::vector<const void*> offsets_;
    std::vector<SurfaceBatch> batches_;
    size_t batch_count_ = 0;
};

}  // namespace nq::npr::classic

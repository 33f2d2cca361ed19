// The entities to draw this frame, in a caller-owned list reserved once: server entities in
// the latest message (not the view entity itself), static entities, the client's temporary
// entities (beam segments, explosion sprites) and the view model, each with its animation
// resolved into the two poses to blend. Filling the list never allocates. Culling (PVS,
// frustum) is the engine's job.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "client/client_state.h"
#include "client/view.h"

namespace nq {

// Same bit values as nqr_entity_flags in nqr_renderer.h.
enum VisibleEntityFlag : uint32_t {
    kVisibleViewModel = 1u << 0,
    kVisibleStatic = 1u << 1,
    kVisibleTemp = 1u << 2,
    kVisibleFullbright = 1u << 3,
};

struct VisibleEntity {
    uint32_t number = 0;  // server entity number; statics and temps are numbered after them
    int model = 0;        // index into ClientState::model_names()
    uint32_t flags = 0;   // VisibleEntityFlag bits
    Vec3 origin{};
    Vec3 angles{};
    float scale = 1;
    int frame = 0;
    PoseBlend pose;  // poses (alias) or images (sprite) to blend
    int skin = 0;
    uint32_t skin_image = 0;  // image within the skin (skin groups resolved)
    uint8_t top_color = 0;    // player colours 0..15
    uint8_t bottom_color = 0;
    bool has_translation = false;  // colormap names a player: translate shirt and pants
    float alpha = 1;
    int effects = 0;
};

class VisibleEntityList {
  public:
    explicit VisibleEntityList(size_t capacity = 4096) : items_(capacity) {}
    void clear() { count_ = 0; }
    bool push(const VisibleEntity& e);  // false (and counted) when full
    std::span<const VisibleEntity> entities() const { return {items_.data(), count_}; }
    size_t size() const { return count_; }
    size_t capacity() const { return items_.size(); }
    size_t dropped() const { return dropped_; }

  private:
    std::vector<VisibleEntity> items_;  // sized once
    size_t count_ = 0;
    size_t dropped_ = 0;
};

// Clears `out` and fills it for the current frame (call after prepare_frame and compute_view).
void collect_visible_entities(const ClientState& client, const ViewResult& view,
                              VisibleEntityList& out);

}  // namespace nq

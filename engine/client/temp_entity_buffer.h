// Entities the client makes up itself each frame (beam segments, explosion sprites): a fixed
// buffer, refilled every frame, never allocating.
#pragma once

#include <array>
#include <cstddef>
#include <span>

#include "formats/server_message.h"

namespace nq {

inline constexpr size_t kMaxTempEntities = 256;

struct TempModelEntity {
    int model = 0;  // index into ClientState::model_names()
    Vec3 origin{};
    Vec3 angles{};
    int frame = 0;
};

class TempEntityBuffer {
  public:
    void clear() { count_ = 0; }
    // False (and counted) when the buffer is full.
    bool push(const TempModelEntity& e) {
        if (count_ == items_.size()) {
            ++dropped_;
            return false;
        }
        items_[count_++] = e;
        return true;
    }
    std::span<const TempModelEntity> entities() const { return {items_.data(), count_}; }
    size_t dropped() const { return dropped_; }

  private:
    std::array<TempModelEntity, kMaxTempEntities> items_{};
    size_t count_ = 0;
    size_t dropped_ = 0;
};

}  // namespace nq

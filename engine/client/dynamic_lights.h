// Dynamic lights (muzzle flashes, rockets, explosions, glowing entities): a fixed table. A light
// is lit while its die time has not passed and its radius is above zero; radius shrinks by
// `decay` units per second.
#pragma once

#include <array>
#include <cstddef>
#include <span>

#include "formats/server_message.h"

namespace nq {

inline constexpr size_t kMaxDynamicLights = 64;

struct DynamicLight {
    int key = 0;  // owner entity number, so an entity's light is reused frame after frame; 0 = none
    Vec3 origin{};
    float radius = 0;
    double die = 0;
    float decay = 0;     // radius lost per second
    float minlight = 0;  // radius below which it no longer lights (muzzle flashes use 32)
    Vec3 color{1, 1, 1};
    bool lit(double time) const { return die >= time && radius > 0; }
};

class DynamicLights {
  public:
    // The slot for `key` (reused if that key already has one), else an unlit slot, else slot 0.
    // The slot is reset to defaults with its key set.
    DynamicLight& allocate(int key, double time);
    // Shrinks every lit light by decay * frame_time.
    void decay(double time, float frame_time);
    void clear();

    std::span<const DynamicLight> all() const { return lights_; }
    size_t lit_count(double time) const;

  private:
    std::array<DynamicLight, kMaxDynamicLights> lights_{};
};

}  // namespace nq

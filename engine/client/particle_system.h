// Fixed-capacity particle storage and physics. All memory is reserved at construction; spawning
// into a full system drops the particle (counted) instead of allocating.
//
// Physics per kind, per second (facts of Quake's particle code):
//   Static       moves at its velocity
//   Gravity,     fall: velocity.z -= gravity * 0.05 (gravity = sv_gravity, 800)
//   SlowGravity
//   Fire         ramp += 5; colour from ramp3; rises by the same gravity term; dies at ramp 6
//   Explode      ramp += 10; colour from ramp1; velocity grows 4x per second; falls; dies at 8
//   Explode2     ramp += 15; colour from ramp2; velocity shrinks 1x per second; falls; dies at 8
//   Blob         velocity grows 4x per second; falls
//   Blob2        horizontal velocity shrinks 4x per second; falls
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "formats/server_message.h"

namespace nq {

inline constexpr size_t kDefaultParticleCapacity = 16384;

enum class ParticleKind : uint8_t {
    Static,
    Gravity,
    SlowGravity,
    Fire,
    Explode,
    Explode2,
    Blob,
    Blob2
};

// Palette ramps of the fire and explosion kinds.
inline constexpr std::array<uint8_t, 8> kParticleRamp1 = {0x6f, 0x6d, 0x6b, 0x69,
                                                          0x67, 0x65, 0x63, 0x61};
inline constexpr std::array<uint8_t, 8> kParticleRamp2 = {0x6f, 0x6e, 0x6d, 0x6c,
                                                          0x6b, 0x6a, 0x68, 0x66};
inline constexpr std::array<uint8_t, 6> kParticleRamp3 = {0x6d, 0x6b, 6, 5, 4, 3};

struct Particle {
    Vec3 origin{};
    Vec3 velocity{};
    double die = 0;  // client time after which it is removed
    float ramp = 0;
    uint8_t color = 0;  // palette index
    ParticleKind kind = ParticleKind::Static;
};

class ParticleSystem {
  public:
    explicit ParticleSystem(size_t capacity = kDefaultParticleCapacity);

    // A fresh particle to fill in, or nullptr when the system is full.
    Particle* spawn();
    void clear();

    // Moves every particle by `frame_time` seconds, then removes those whose time (or ramp) is
    // over at client time `time`.
    void update(double time, float frame_time, float gravity);

    std::span<const Particle> particles() const { return {items_.data(), count_}; }
    size_t size() const { return count_; }
    size_t capacity() const { return items_.size(); }
    size_t dropped() const { return dropped_; }  // spawns refused because the system was full

  private:
    void step(Particle& p, float frame_time, float gravity) const;

    std::vector<Particle> items_;  // sized once; [0, count_) are alive
    size_t count_ = 0;
    size_t dropped_ = 0;
};

}  // namespace nq

// Randomness a style can show on screen: every random choice is a hash of what it is for — the
// style's seed, a stable primitive id (a BSP face or edge, an MDL triangle or edge, a particle's
// slot and spawn time) and the boil epoch — never a running cursor or the clock. So the same demo
// frame draws the same strokes in every run, a paused frame never changes, and a style that
// "boils" redraws its strokes at the same demo-time phase whatever the frame rate.
//
// The hash: each word is mixed into the state by a bijective 32-bit finaliser (xor-shift and
// multiply, "lowbias32" constants from Wellons' hash-prospector search), so every input bit
// reaches every output bit. kStableRandomGlsl is the same function for shaders; a test checks
// that the GPU's bits equal these.
#pragma once

#include <cstdint>
#include <initializer_list>

namespace nq::npr::coherence {

constexpr uint32_t mix32(uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

// The hash of a few words, order-sensitive: h = mix32(h ^ mix32(word + k)) from a fixed start.
constexpr uint32_t hash_words(std::initializer_list<uint32_t> words) {
    uint32_t h = 0x6a09e667u;
    for (uint32_t w : words) h = mix32(h ^ mix32(w + 0x9e3779b9u));
    return h;
}

// A hash's top 24 bits as a float in [0, 1), exactly representable.
constexpr float unit_float(uint32_t h) {
    return static_cast<float>(h >> 8) * (1.0f / 16777216.0f);
}

// The epoch a style boiling at `hz` draws in at `demo_time` seconds: floor(demo_time * hz), so
// 12 gives new strokes every 1/12 s of demo time ("on twos" at 24 fps) at any frame rate.
// `hz` <= 0 is frozen: epoch 0 at every time. Times before 0 count as 0.
uint32_t boil_epoch(double demo_time, double hz);

// What a random value belongs to. The kinds keep a face and an edge with the same index apart.
enum class PrimitiveKind : uint32_t {
    world_face = 1,
    world_edge = 2,
    model_triangle = 3,
    model_edge = 4,
    particle = 5,
    sprite = 6,
};

// A stable id: the kind, what owns the primitive (a model id, an entity number; 0 for the
// world) and its index there.
constexpr uint32_t primitive_id(PrimitiveKind kind, uint32_t owner, uint32_t index) {
    return hash_words({static_cast<uint32_t>(kind), owner, index});
}

// A particle is its slot and the demo time it was born at, in milliseconds: a slot reused by a
// new particle draws differently, one particle draws alike for its whole life.
uint32_t particle_id(uint32_t slot, double spawn_time);

// The values one primitive draws in one epoch: stream k is its k-th independent value (stroke
// offset, length, angle...), the same for the same (seed, primitive, epoch, k) anywhere.
class StableRandom {
  public:
    constexpr StableRandom(uint32_t seed, uint32_t primitive, uint32_t epoch)
        : seed_(seed), primitive_(primitive), epoch_(epoch) {}

    constexpr uint32_t bits(uint32_t stream) const {
        return hash_words({seed_, primitive_, epoch_, stream});
    }
    constexpr float unit(uint32_t stream) const { return unit_float(bits(stream)); }
    constexpr float range(uint32_t stream, float lo, float hi) const {
        return lo + (hi - lo) * unit(stream);
    }

  private:
    uint32_t seed_, primitive_, epoch_;
};

// GLSL (330 core) of the same functions: nq_mix32(uint), nq_hash4(uint, uint, uint, uint) (=
// hash_words of those four words, StableRandom::bits) and nq_unit(uint).
extern const char* const kStableRandomGlsl;

}  // namespace nq::npr::coherence

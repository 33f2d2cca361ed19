// The server's random numbers (monster chase directions, QuakeC's random()): a small seeded
// generator, so a recorded game replays the same way from the same seed. xorshift32: fast, and
// its whole state is one word.
#pragma once

#include <cstdint>

namespace nq::server {

class GameRandom {
  public:
    explicit GameRandom(uint32_t seed_value = 1) { seed(seed_value); }

    // Zero would stay zero forever in xorshift, so it stands for another fixed seed.
    void seed(uint32_t value) { state_ = value ? value : 0x9e3779b9u; }

    uint32_t next_u32() {
        state_ ^= state_ << 13;
        state_ ^= state_ >> 17;
        state_ ^= state_ << 5;
        return state_;
    }

    // Uniform in [0, 1): the top 24 bits, so every value is exact in a float.
    float next() { return float(next_u32() >> 8) * (1.0f / 16777216.0f); }

  private:
    uint32_t state_ = 1;
};

}  // namespace nq::server

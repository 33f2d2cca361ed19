// The client's random numbers (particle spread, light flicker, animation phase): a small
// seedable generator, so that a seeded client plays a demo identically every time.
#pragma once

#include <cstdint>

namespace nq {

class ClientRandom {
  public:
    explicit ClientRandom(uint64_t seed = 1) { reseed(seed); }
    void reseed(uint64_t seed);

    uint32_t next();  // 32 random bits
    // 0..32767, the range of C's rand() on the platforms Quake's effects were tuned on.
    int rand15() { return static_cast<int>(next() >> 17); }
    float unit() { return static_cast<float>(next() >> 8) * (1.0f / 16777216.0f); }  // [0, 1)

  private:
    uint64_t state_ = 0;
};

}  // namespace nq

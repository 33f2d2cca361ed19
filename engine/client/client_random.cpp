#include "client/client_random.h"

namespace nq {

// SplitMix64: tiny, fast, and every seed (0 included) gives a full-period stream.
void ClientRandom::reseed(uint64_t seed) {
    state_ = seed;
}

uint32_t ClientRandom::next() {
    state_ += 0x9E3779B97F4A7C15ull;
    uint64_t z = state_;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return static_cast<uint32_t>(z >> 32);
}

}  // namespace nq

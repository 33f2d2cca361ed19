#include "coherence/stable_random.h"

#include <algorithm>
#include <cmath>

namespace nq::npr::coherence {

uint32_t boil_epoch(double demo_time, double hz) {
    if (!(hz > 0.0) || !(demo_time > 0.0)) return 0;
    // A frame that lands on a boundary (10 / 30 s at 12 Hz is 3.9999999999999996 epochs in
    // doubles) belongs to the epoch that starts there, at every frame rate.
    constexpr double kBoundarySlack = 1e-7;
    const double epoch = std::floor(demo_time * hz + kBoundarySlack);
    return epoch >= 4294967295.0 ? 0xffffffffu : static_cast<uint32_t>(epoch);
}

uint32_t particle_id(uint32_t slot, double spawn_time) {
    const double ms = std::floor(std::max(spawn_time, 0.0) * 1000.0 + 0.5);
    const uint32_t born = ms >= 4294967295.0 ? 0xffffffffu : static_cast<uint32_t>(ms);
    return primitive_id(PrimitiveKind::particle, slot, born);
}

const char* const kStableRandomGlsl = R"(
uint nq_mix32(uint x) {
    x ^= x >> 16u;
    x *= 0x7feb352du;
    x ^= x >> 15u;
    x *= 0x846ca68bu;
    x ^= x >> 16u;
    return x;
}
uint nq_hash_step(uint h, uint w) { return nq_mix32(h ^ nq_mix32(w + 0x9e3779b9u)); }
uint nq_hash4(uint a, uint b, uint c, uint d) {
    return nq_hash_step(nq_hash_step(nq_hash_step(nq_hash_step(0x6a09e667u, a), b), c), d);
}
float nq_unit(uint h) { return float(h >> 8u) * (1.0 / 16777216.0); }
)";

}  // namespace nq::npr::coherence

// Lightning and grappling beams (TE_LIGHTNING1/2/3, TE_BEAM): each lives 0.2 s after its last
// message and is drawn as its model repeated every 30 units from start to end, turned along the
// beam with a random roll. A new beam from the same owner entity replaces the old one; a beam
// owned by the view entity starts at that entity's current origin.
#pragma once

#include <array>
#include <cstddef>
#include <span>

#include "client/client_random.h"
#include "client/temp_entity_buffer.h"

namespace nq {

inline constexpr size_t kMaxBeams = 32;
inline constexpr double kBeamLifetime = 0.2;
inline constexpr float kBeamSegmentLength = 30;

struct Beam {
    int entity = 0;
    int model = 0;  // 0 = free slot
    double end_time = 0;
    Vec3 start{}, end{};
};

class Beams {
  public:
    // False when every slot holds a live beam of another entity (the beam is dropped).
    bool start(int entity, int model, double time, const Vec3& start, const Vec3& end);
    void clear() { beams_.fill(Beam{}); }

    void build_segments(double time, int view_entity, const Vec3& view_origin, ClientRandom& random,
                        TempEntityBuffer& out);

    std::span<const Beam> beams() const { return beams_; }

  private:
    std::array<Beam, kMaxBeams> beams_{};
};

// Pitch and yaw (degrees, whole numbers in 0..360) that point along `direction`.
Vec3 beam_angles(const Vec3& direction);

}  // namespace nq

#include "sound/spatialize.h"

#include <algorithm>
#include <cmath>

namespace nq {

StereoVolume spatialize(const SoundVec3& origin, float master_volume, float dist_mult,
                        const Listener& listener) {
    SoundVec3 dir{origin[0] - listener.origin[0], origin[1] - listener.origin[1],
                  origin[2] - listener.origin[2]};
    const float length = std::sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
    if (length > 0) {
        for (float& d : dir) d /= length;
    }
    const float dist = length * dist_mult;
    const float dot =
        listener.right[0] * dir[0] + listener.right[1] * dir[1] + listener.right[2] * dir[2];
    const float right_scale = (1.0f - dist) * (1.0f + dot);
    const float left_scale = (1.0f - dist) * (1.0f - dot);
    StereoVolume v;
    v.right = std::max(0, int(master_volume * right_scale));
    v.left = std::max(0, int(master_volume * left_scale));
    return v;
}

}  // namespace nq

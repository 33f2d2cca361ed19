#include "client/dynamic_lights.h"

#include <algorithm>

namespace nq {

DynamicLight& DynamicLights::allocate(int key, double time) {
    DynamicLight* slot = nullptr;
    if (key != 0) {
        for (DynamicLight& l : lights_) {
            if (l.key == key) {
                slot = &l;
                break;
            }
        }
    }
    if (!slot) {
        for (DynamicLight& l : lights_) {
            if (!l.lit(time)) {
                slot = &l;
                break;
            }
        }
    }
    if (!slot) slot = &lights_[0];  // all busy: Quake overwrites the first one
    *slot = DynamicLight{};
    slot->key = key;
    return *slot;
}

void DynamicLights::decay(double time, float frame_time) {
    for (DynamicLight& l : lights_) {
        if (!l.lit(time)) continue;
        l.radius = std::max(0.0f, l.radius - frame_time * l.decay);
    }
}

void DynamicLights::clear() {
    lights_.fill(DynamicLight{});
}

size_t DynamicLights::lit_count(double time) const {
    return static_cast<size_t>(
        std::count_if(lights_.begin(), lights_.end(), [&](const auto& l) { return l.lit(time); }));
}

}  // namespace nq

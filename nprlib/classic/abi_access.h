// Safe reading of the size-prefixed ABI structs: arrays are walked with the stride of their
// first element's `size` (nqr_at), and a struct shorter than the prefix this build knows is
// refused rather than read past its end (an older engine that lacks the fields we use).
#pragma once

#include <cstddef>
#include <cstdint>

#include "nqr_renderer.h"

namespace nq::npr::classic {

template <class T>
bool has_known_prefix(const T* item) {
    return item != nullptr && item->size >= sizeof(T);
}

// A frame is read from its ABI 1.0 prefix on: fields appended since are checked one by one.
inline bool frame_readable(const nqr_frame* frame) {
    return frame != nullptr && frame->size >= offsetof(nqr_frame, view_planes);
}
inline bool frame_has_view_planes(const nqr_frame& frame) {
    return frame.size >= offsetof(nqr_frame, view_planes) + sizeof(frame.view_planes);
}

// An entity's light is read from its ABI 1.0 fields (up to the ambient cube); the light list
// appended in 1.4 is checked on its own.
inline bool light_readable(const nqr_entity_light& light) {
    return light.size >= offsetof(nqr_entity_light, ambient_cube) + sizeof(light.ambient_cube);
}
inline bool light_has_sources(const nqr_entity_light& light) {
    return light.size >= offsetof(nqr_entity_light, lights) + sizeof(light.lights);
}

// An entity is read from its ABI 1.0 prefix on (its light up to the ambient cube).
inline bool entity_readable(const nqr_entity* entity) {
    return entity != nullptr &&
           entity->size >= offsetof(nqr_entity, light) + offsetof(nqr_entity_light, num_lights);
}

// An entity whose model can be on screen: readable, not flagged outside the view frustum nor
// hidden behind the world.
inline bool entity_in_view(const nqr_entity* entity) {
    return entity_readable(entity) &&
           (entity->flags & (NQR_ENTITY_OUTSIDE_VIEW | NQR_ENTITY_OCCLUDED)) == 0;
}

// Element i of a size-prefixed array (its first element gives the stride).
template <class T>
const T& abi_element(const T* array, uint32_t i) {
    return *nqr_at(T, array, i);
}

// Whether an array of `count` elements can be walked: stride known and large enough.
template <class T>
bool abi_array_usable(const T* array, uint32_t count) {
    return count == 0 || has_known_prefix(array);
}

}  // namespace nq::npr::classic

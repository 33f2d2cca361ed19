// Safe reading of the size-prefixed ABI structs, for every style and the engine's defaults.
// One rule: a field is read only when the struct's `size` covers it (an older engine's struct
// lacks what was appended after it), and arrays are walked with the stride of their first
// element's `size` (nqr_at). What a struct had in ABI 1.0 is its readable prefix; fields
// appended since are asked for one by one.
#pragma once

#include <cstddef>
#include <cstdint>

#include "nqr_renderer.h"

// The offset just past `field` of `type`: the size a struct needs for the field to be read.
#define NQR_FIELD_END(type, field) (offsetof(type, field) + sizeof(((type*)nullptr)->field))

namespace nq::npr {

// The rule itself: `item` is there and its size reaches `end` bytes.
template <class T>
bool size_covers(const T* item, size_t end) {
    return item != nullptr && item->size >= end;
}

// Structs unchanged since ABI 1.0 (cameras, models, particles...): every field this build knows.
template <class T>
bool has_known_prefix(const T* item) {
    return size_covers(item, sizeof(T));
}

// A frame: its 1.0 fields, then the view planes appended in 1.1.
inline bool frame_readable(const nqr_frame* frame) {
    return size_covers(frame, offsetof(nqr_frame, view_planes));
}
inline bool frame_has_view_planes(const nqr_frame& frame) {
    return size_covers(&frame, NQR_FIELD_END(nqr_frame, view_planes));
}

// An entity's light: its 1.0 fields (up to the ambient cube), then the light list of 1.4.
inline bool light_readable(const nqr_entity_light& light) {
    return size_covers(&light, NQR_FIELD_END(nqr_entity_light, ambient_cube));
}
inline bool light_has_sources(const nqr_entity_light& light) {
    return size_covers(&light, NQR_FIELD_END(nqr_entity_light, lights));
}

// An entity: its 1.0 fields, its light up to the ambient cube.
inline bool entity_readable(const nqr_entity* entity) {
    return size_covers(entity,
                       offsetof(nqr_entity, light) + offsetof(nqr_entity_light, num_lights));
}

// An entity whose model can be on screen: readable, not flagged outside the view frustum nor
// hidden behind the world.
inline bool entity_in_view(const nqr_entity* entity) {
    return entity_readable(entity) &&
           (entity->flags & (NQR_ENTITY_OUTSIDE_VIEW | NQR_ENTITY_OCCLUDED)) == 0;
}

// Entity alpha as drawn: ABI 1 = opaque; values <= 0 or >= 1 are treated as opaque (0 is what an
// unset alpha looks like in the protocol extensions that carry one).
inline float entity_alpha(float alpha) {
    return (alpha <= 0.0f || alpha >= 1.0f) ? 1.0f : alpha;
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

}  // namespace nq::npr

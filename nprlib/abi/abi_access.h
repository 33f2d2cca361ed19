// Safe reading of the size-prefixed ABI structs, for every style and the engine's defaults.
// One rule: a field is read only when the struct's `size` covers it (an older engine's struct
// lacks what was appended after it), and arrays are walked with the stride of their first
// element's `size` (nqr_at). ABI 2.0 is the baseline every 2.x engine fills.
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

// The one readiness policy: a struct is read when its size covers every field this build
// knows. (A field appended in a later 2.x minor is then asked for on its own with size_covers
// and NQR_FIELD_END, and a struct without it is still read.)
template <class T>
bool has_known_prefix(const T* item) {
    return size_covers(item, sizeof(T));
}

// Structs that point to others are read when those are too.
inline bool camera_readable(const nqr_camera* camera) {
    return has_known_prefix(camera);
}
inline bool frame_readable(const nqr_frame* frame) {
    return has_known_prefix(frame) && camera_readable(frame->camera);
}
inline bool light_readable(const nqr_entity_light* light) {
    return has_known_prefix(light) && (light->num_lights == 0 || has_known_prefix(light->lights));
}
inline bool entity_readable(const nqr_entity* entity) {
    return has_known_prefix(entity) && light_readable(entity->light);
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

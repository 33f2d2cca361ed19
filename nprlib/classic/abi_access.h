// Safe reading of the size-prefixed ABI structs: arrays are walked with the stride of their
// first element's `size` (nqr_at), and a struct shorter than the prefix this build knows is
// refused rather than read past its end (an older engine that lacks the fields we use).
#pragma once

#include <cstdint>

#include "nqr_renderer.h"

namespace nq::npr::classic {

template <class T>
bool has_known_prefix(const T* item) {
    return item != nullptr && item->size >= sizeof(T);
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

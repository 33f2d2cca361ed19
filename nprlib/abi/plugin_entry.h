// What every C++ renderer plugin's nqr_get_renderer checks before handing out its table: the
// engine speaks our ABI major version and its services struct is at least as large as the one
// this plugin was compiled against.
#pragma once

#include <cstdint>

#include "nqr_renderer.h"

namespace nq::npr {

inline bool engine_abi_compatible(uint32_t engine_abi_version, const nqr_engine* engine) {
    return NQR_ABI_MAJOR(engine_abi_version) == NQR_ABI_VERSION_MAJOR && engine != nullptr &&
           engine->size >= sizeof(nqr_engine);
}

}  // namespace nq::npr

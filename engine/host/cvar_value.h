/* The view of one cvar's value handed to renderer plugins through the C plugin ABI: plain C,
 * no C++ types, so a plugin written or compiled differently can read it directly.
 *
 * Lifetime: a pointer to this struct (from nq::Cvar::value_ptr()) stays valid, at the same
 * address, for the whole lifetime of the CvarRegistry that owns the cvar: cvars are never
 * removed, not when their plugin unloads, not when they are registered again.
 * `string` points into registry storage and changes when the value changes: it is valid until
 * the next change of this cvar; copy the text if it must be kept. `modified_count` grows by one
 * on every change, so a plugin can poll it once per frame instead of registering a callback.
 * Single-threaded: read it on the thread that runs the command system. */
#pragma once

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct nq_cvar_value {
    float value;             /* the string read as a number (0 when it is not one) */
    int32_t integer;         /* value truncated toward zero, saturated to the int32 range */
    const char* string;      /* the text value, never NULL */
    uint32_t modified_count; /* number of changes since the cvar was created */
} nq_cvar_value;

#ifdef __cplusplus
}

namespace nq {
using CvarValue = ::nq_cvar_value;
}
#endif

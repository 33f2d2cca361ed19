// The view of one cvar's value handed to renderer plugins: the ABI's nqr_cvar (plain C, starts
// with its size), so the registry's storage is exactly what a plugin reads.
//
// Lifetime: a pointer to it (from nq::Cvar::value_ptr()) stays valid, at the same address, for
// the whole lifetime of the CvarRegistry that owns the cvar: cvars are never removed, not when
// their plugin unloads, not when they are registered again. `string` points into registry
// storage and is valid until the next change of this cvar. `modified_count` grows by one on
// every change, so a plugin can poll it once per frame instead of registering a callback.
// Single-threaded: read it on the thread that runs the command system.
#pragma once

#include "nqr_renderer.h"

namespace nq {
using CvarValue = ::nqr_cvar;
}

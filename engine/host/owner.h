// Who registered a cvar callback or a command: the engine itself or one loaded renderer plugin.
// Plugins are shared libraries that can be unloaded while the game runs; everything they
// registered is removed by their owner id before the library's code goes away.
#pragma once

#include <cstdint>

namespace nq {

using OwnerId = uint32_t;

inline constexpr OwnerId kEngineOwner = 0;
// A cvar whose registrant was unloaded: the cvar and its value live on, unowned.
inline constexpr OwnerId kNoOwner = 0xffffffffu;

}  // namespace nq

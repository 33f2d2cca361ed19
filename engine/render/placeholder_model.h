// What stands in for a model that could not be loaded (demos name models the data may lack,
// such as some gibs and heads): a 16-unit box, one frame, one solid-colour skin.
#pragma once

#include <cstdint>
#include <memory>

#include "render/alias_model.h"

namespace nq {

// Palette index 251 lies in Quake's fullbright range (224..255) and is a saturated red in the
// id and LibreQuake palettes: the box stays visible in the dark and reads as "missing".
inline constexpr uint8_t kPlaceholderColor = 251;
inline constexpr float kPlaceholderHalfSize = 8.0f;

// Every vertex uses normal 5 of Quake's 162-normal table, (0, 0, 1): lit as if facing up.
std::shared_ptr<const AliasModelData> make_placeholder_alias();

}  // namespace nq

// Quake's animated brush textures: a chain "+0name".."+9name" shows one frame per 0.2 s (time x 5
// frames per second, cycling); a brush entity whose frame is not 0 uses the alternate chain
// "+aname".."+jname" when there is one (buttons and doors that change when triggered).
#pragma once

#include <cstdint>

#include "nqr_renderer.h"

namespace nq::npr::classic {

inline constexpr double kTextureFramesPerSecond = 5.0;  // 0.2 s per frame

// The texture index to draw for surface texture `texture` at `time`; `alternate` = the entity's
// frame is not 0. Returns `texture` unchanged when it is not animated or indices are invalid.
int32_t animated_texture(const nqr_brush_model& brush, int32_t texture, double time,
                         bool alternate);

}  // namespace nq::npr::classic

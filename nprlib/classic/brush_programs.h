// The three brush-surface programs of the classic look (lightmapped, sky, warped liquid). All
// share one vertex shader; every fragment shader also writes the view-space normal to output 1
// (encoded n * 0.5 + 0.5) for plugins that render a normal buffer.
#pragma once

#include <string>

#include "gl/program.h"

namespace nq::npr::classic {

struct BrushPrograms {
    gl::Program lit;     // texture x lightmap x overbright + fullbright mask; alpha cut-off
    gl::Program sky;     // two scrolling layers
    gl::Program liquid;  // turbulent warp, unlit

    // Builds all three; false and `error` set if one fails.
    bool build(gl::ObjectTracker* tracker, std::string& error);
    void reset();
};

// Texture units the brush programs read.
inline constexpr int kUnitTexture = 0;     // lit/liquid base, sky back layer
inline constexpr int kUnitFullbright = 1;  // lit fullbright mask, sky front layer
inline constexpr int kUnitLightmap = 2;    // lightmap atlas (2D array)

}  // namespace nq::npr::classic

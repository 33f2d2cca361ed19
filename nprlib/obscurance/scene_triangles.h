// What a frame puts in front of the camera, as triangles in view space, for the ray-traced
// obscurance reference (scene_file.h): the world's surfaces, every brush entity's, and every
// alias entity posed as it is drawn (its two poses blended); sky and liquid surfaces are kept
// but not solid. Sprites, particles and the view model (drawn with a depth range of its own)
// are left out. Read through the ABI only, as a renderer would.
#pragma once

#include <span>

#include "nqr_renderer.h"
#include "obscurance/scene_file.h"

namespace nq::npr::obscurance {

// `models`: every registered model (the frame refers to them by id).
ObscuranceScene collect_scene(const nqr_frame& frame, std::span<const nqr_model* const> models);

}  // namespace nq::npr::obscurance
